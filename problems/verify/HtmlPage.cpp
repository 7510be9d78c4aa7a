#include "problems/verify/HtmlPage.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "problems/output/files/XmlText.hpp"

namespace beamrotor::verify {

namespace {

constexpr const char* kStyle =
    "body{font-family:sans-serif;max-width:1000px;margin:2em auto;color:#222}"
    "table{border-collapse:collapse;margin:0.5em 0 1.5em}"
    "td,th{border:1px solid #ccc;padding:2px 8px;text-align:right}"
    "td:first-child,td:nth-child(2),th{text-align:left}"
    ".pass{color:#1a7f37}.fail{color:#c62828;font-weight:bold}"
    "tr.na td{color:#777}tr.note td{text-align:left;font-size:90%;color:#555}"
    "figure{margin:1.5em 0}figcaption{font-style:italic;margin-top:0.3em}"
    "svg{max-width:100%;height:auto}";

std::string scientific(double x, int digits) {
  char text[40];
  std::snprintf(text, sizeof text, "%.*g", digits, x);
  return text;
}

/// The paper's figure beside a check whose reference is not it, with the reason.
void writePaperNote(std::ostringstream& html, const Check& c) {
  if (!c.paper) return;
  html << "<tr class=\"note\"><td colspan=\"8\">paper prints " << scientific(*c.paper, 9)
       << " (differs from the computed value by "
       << scientific(std::abs(c.computed - *c.paper) / std::abs(*c.paper), 2)
       << " relative): " << xmlEscape(c.reason) << "</td></tr>\n";
}

void writeDeck(std::ostringstream& html, const DeckChecks& d) {
  html << "<h3>" << xmlEscape(d.deck);
  if (!d.title.empty()) html << ": " << xmlEscape(d.title);
  html << "</h3>\n";
  if (!d.error.empty()) {
    html << "<p class=\"fail\">not solved: " << xmlEscape(d.error) << "</p>\n";
    return;
  }
  if (d.checks.empty() && d.notApplied.empty()) {
    html << "<p>no checks (solved in " << scientific(d.seconds, 3) << " s)</p>\n";
    return;
  }
  html << "<table><tr><th>check</th><th>run</th><th>quantity</th><th>computed</th>"
          "<th>reference</th><th>rel. error</th><th>tolerance</th><th>result</th></tr>\n";
  for (const auto& [label, c] : d.checks) {
    html << "<tr><td>" << xmlEscape(c.name) << "</td><td>" << xmlEscape(label) << "</td><td>"
         << xmlEscape(c.quantity) << "</td><td>" << scientific(c.computed, 9) << "</td><td>"
         << scientific(c.reference, 9) << "</td><td>" << scientific(c.relError(), 2) << "</td><td>"
         << scientific(c.tolerance, 2) << "</td><td class=\""
         << (c.pass() ? "pass\">pass" : "fail\">FAIL") << "</td></tr>\n";
    writePaperNote(html, c);
  }
  for (const NotApplied& n : d.notApplied)
    html << "<tr class=\"na\"><td>" << xmlEscape(n.name) << "</td><td>" << xmlEscape(n.label)
         << "</td><td colspan=\"5\">" << xmlEscape(n.why)
         << "</td><td>did not apply</td></tr>\n";
  html << "</table>\n";
}

void writeFigure(std::ostringstream& html, const ReportFigure& f) {
  html << "<figure>\n<h3>" << xmlEscape(f.title) << "</h3>\n";
  const std::string svg = inlineSvg(f.svg);
  html << (svg.empty() ? "<p class=\"fail\">chart not drawn (is gnuplot installed?)</p>" : svg)
       << "\n<figcaption>" << xmlEscape(f.caption) << "</figcaption>\n</figure>\n";
}

}  // namespace

std::string inlineSvg(const std::filesystem::path& svg) {
  std::ifstream in(svg);
  if (!in) return {};
  std::stringstream s;
  s << in.rdbuf();
  const std::string text = s.str();
  const auto start = text.find("<svg");
  return start == std::string::npos ? std::string() : text.substr(start);
}

std::string reportHtml(const ReportContent& content) {
  int checks = 0, passed = 0, notApplied = 0;
  for (const DeckChecks& d : content.decks) {
    notApplied += int(d.notApplied.size());
    for (const auto& entry : d.checks) {
      ++checks;
      passed += entry.second.pass();
    }
  }
  std::ostringstream html;
  html << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n"
       << "<title>beamrotor verification report</title>\n<style>" << kStyle
       << "</style></head><body>\n<h1>beamrotor verification report</h1>\n<p>"
       << xmlEscape(content.generated) << ". Regenerate with <code>make report</code> or "
       << "<code>beamrotor report --out DIR</code>.</p>\n"
       << "<h2>1. Checks of the shipped decks</h2>\n<p>" << passed << " of " << checks
       << " checks pass, " << checks - passed << " fail, " << notApplied
       << " did not apply (their when: condition is false at the deck's parameter values; each "
          "is listed under its deck with the condition). Each check compares a computed "
          "quantity with the deck's closed form or published figure; where a paper prints "
          "another figure, the row below the check gives it and the reason.</p>\n";
  for (const DeckChecks& d : content.decks) writeDeck(html, d);
  html << "<h2>2. Convergence and work-precision</h2>\n";
  if (content.convergence.empty())
    html << "<p>No convergence study found: these charts come from <code>beamrotor converge"
            "</code> (written to DIR/convergence/) once that command is available.</p>\n";
  for (const ReportFigure& f : content.convergence) writeFigure(html, f);
  if (!content.notConverged.empty()) {
    html << "<p>Decks without a convergence study:</p>\n<ul>\n";
    for (const auto& [deck, why] : content.notConverged)
      html << "<li><code>" << xmlEscape(deck) << "</code>: " << xmlEscape(why) << "</li>\n";
    html << "</ul>\n";
  }
  html << "<h2>3. Where methods fail, and the remedies</h2>\n";
  for (const ReportFigure& f : content.failures) writeFigure(html, f);
  html << "</body></html>\n";
  return html.str();
}

}  // namespace beamrotor::verify
