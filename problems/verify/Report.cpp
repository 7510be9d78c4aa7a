#include "problems/verify/Report.hpp"

#include <algorithm>
#include <ctime>
#include <fstream>

#include "problems/verify/HtmlPage.hpp"

namespace beamrotor::verify {

namespace {

namespace fs = std::filesystem;

/// Hook for the convergence study (`beamrotor converge`, another branch): every SVG chart
/// under DIR/convergence/, sorted, titled by its path, e.g. "cantilever/error_vs_dofs".
std::vector<ReportFigure> convergenceFigures(const fs::path& dir) {
  std::vector<ReportFigure> figures;
  if (!fs::is_directory(dir)) return figures;
  for (const auto& entry : fs::recursive_directory_iterator(dir))
    if (entry.is_regular_file() && entry.path().extension() == ".svg") {
      const fs::path relative = fs::relative(entry.path(), dir).replace_extension();
      figures.push_back({"Convergence: " + relative.generic_string(),
                         "Error against cost for each method, as written by beamrotor converge "
                         "(see convergence.json beside it for the numbers).",
                         entry.path()});
    }
  std::sort(figures.begin(), figures.end(),
            [](const ReportFigure& a, const ReportFigure& b) { return a.svg < b.svg; });
  return figures;
}

std::string generatedLine() {
  const std::time_t now = std::time(nullptr);
  char stamp[32];
  std::strftime(stamp, sizeof stamp, "%Y-%m-%d %H:%M", std::gmtime(&now));
  return std::string("beamrotor ") + BEAMROTOR_VERSION + ", generated " + stamp + " UTC";
}

}  // namespace

ReportSummary writeReport(const ReportOptions& options, std::ostream& log) {
  ReportContent content;
  content.generated = generatedLine();
  // 1. The decks' checks.
  log << "checking the decks in " << options.problemsDir.string() << "\n";
  content.decks = runDeckChecks(decksIn(options.problemsDir));
  ReportSummary summary;
  for (const DeckChecks& d : content.decks) {
    log << "  " << d.deck << (d.error.empty() ? "" : ": not solved") << "\n";
    summary.unsolvedDecks += !d.error.empty();
    for (const auto& entry : d.checks) {
      ++summary.checks;
      summary.failedChecks += !entry.second.pass();
    }
  }
  // 2. The failure-case studies, drawn into DIR/charts.
  log << "running the failure-case studies\n";
  const fs::path charts = options.outDir / "charts";
  for (const StudyChart& chart : failureCharts(options.failures)) {
    writeStudyChart(charts, chart);
    content.failures.push_back({chart.title, chart.caption, charts / (chart.name + ".svg")});
  }
  // 3. The convergence charts, when a converge run left them.
  content.convergence = convergenceFigures(options.outDir / "convergence");
  // 4. The page.
  summary.page = options.outDir / "index.html";
  std::ofstream page(summary.page);
  page << reportHtml(content);
  if (!page) throw std::runtime_error("cannot write " + summary.page.string());
  return summary;
}

}  // namespace beamrotor::verify
