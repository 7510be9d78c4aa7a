// Shared gnuplot chart pieces (see ChartParts.hpp).
#include "problems/output/files/ChartParts.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <sstream>

#include "problems/output/files/Gnuplot.hpp"

namespace beamrotor {

namespace {

/// Line colours, in the order curves are drawn: ten hues far apart (blue, red, green, purple,
/// orange, teal, brown, magenta, grey, olive), dark enough to read on white.
constexpr const char* kColours[] = {"#1f4e9c", "#c0392b", "#2e8b57", "#8e44ad", "#d35400",
                                    "#0e8f9e", "#7b4a12", "#d0338a", "#555555", "#8a8a00"};
constexpr int kColourCount = int(std::size(kColours));
/// gnuplot dash types the curves cycle through: solid, dashed, dot-dash. Three against ten
/// colours: the pair (colour, dash) repeats only after 30 curves.
constexpr int kDashTypes[] = {1, 2, 4};
constexpr int kDashCount = int(std::size(kDashTypes));

}  // namespace

std::string colour(std::size_t i) {
  return std::string("linecolor rgb '") + kColours[i % kColourCount] + "'";
}

std::string lineStyle(std::size_t i) {
  return colour(i) + " dashtype " + std::to_string(kDashTypes[i % kDashCount]);
}

std::size_t distinctLineStyles() {
  return std::size_t(kColourCount) * kDashCount;  // 10 and 3 are coprime
}

std::string colourValue(std::size_t i) {
  return std::string("0x") + (kColours[i % kColourCount] + 1);
}

std::string number(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6g", x);
  return buffer;
}

std::string labelNumber(double x, double scale) {
  constexpr double kRoundOff = 1e-9;
  if (x == 0 || std::abs(x) <= kRoundOff * std::abs(scale)) return "0";
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", x);
  return text;
}

std::string logAxis(const std::string& axis, double low, double high) {
  if (!(low > 0) || !(high >= low) || !std::isfinite(high))
    return "  set logscale " + axis + "\n  set format " + axis + " '%g'\n";
  const int first = int(std::floor(std::log10(low) + 1e-9));
  const int last = std::max(first + 1, int(std::ceil(std::log10(high) - 1e-9)));
  constexpr int kMostLabels = 8;
  const int step = (last - first + kMostLabels - 1) / kMostLabels;
  std::ostringstream s;
  s << "  set logscale " << axis << "\n  set " << axis << "range [1e" << first << ":1e" << last
    << "]\n  set " << axis << "tics 1e" << first << ", " << number(std::pow(10.0, step))
    << "\n  set m" << axis << "tics " << (step == 1 ? 10 : step) << "\n  set format " << axis
    << " '10^{%T}'\n";
  return s.str();
}

void PositiveRange::include(double v) {
  if (!(v > 0) || !std::isfinite(v)) return;
  low = low > 0 ? std::min(low, v) : v;
  high = std::max(high, v);
}

std::string logAxis(const std::string& axis, const PositiveRange& range) {
  return logAxis(axis, range.low, range.high);
}

int textWidth(const std::string& text) {
  // UTF-8 continuation bytes do not start a character.
  const auto characters = std::count_if(text.begin(), text.end(), [](char c) {
    return (static_cast<unsigned char>(c) & 0xC0) != 0x80;
  });
  return int(8 * characters);
}

int keyWidth(const std::vector<std::string>& titles) {
  int widest = 0;
  for (const std::string& t : titles) widest = std::max(widest, textWidth(t));
  constexpr int kSampleAndGaps = 90;  // gnuplot's sample line, its gaps and the border space
  return widest + kSampleAndGaps;
}

std::string captionText(const std::string& caption) {
  std::string out, line;
  std::istringstream lines(caption);
  while (std::getline(lines, line)) out += (out.empty() ? "" : ".\"\\n\".") + gnuplotText(line);
  return out.empty() ? gnuplotText("") : out;
}

std::string panelLayout(int rows, int columns, const std::string& caption, int width, int height,
                        int rightMargin) {
  const auto fractionX = [&](double px) { return number(px / width); };
  const auto fractionY = [&](double px) { return number(px / height); };
  const auto lines = 1 + std::count(caption.begin(), caption.end(), '\n');
  return "  set multiplot layout " + std::to_string(rows) + "," + std::to_string(columns) +
         " title " + captionText(caption) + " font ',13' margins " + fractionX(100) + "," +
         fractionX(width - double(rightMargin)) + "," + fractionY(60) + "," +
         fractionY(height - 60.0 - 20.0 * double(lines)) + " spacing " +
         fractionX(columns > 1 ? 100 : 0) + "," + fractionY(rows > 1 ? 75 : 0) + "\n" +
         // Compact tick labels (1e-05, not 1×10^-5), so that the y label fits the margin.
         "  set format y '%g'\n";
}

std::string viewLayout(int rows, int columns, const std::string& caption) {
  return "  set multiplot layout " + std::to_string(rows) + "," + std::to_string(columns) +
         " title " + captionText(caption) + " font ',13'\n  set format y '%g'\n";
}

}  // namespace beamrotor
