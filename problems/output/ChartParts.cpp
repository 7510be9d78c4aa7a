// Shared gnuplot chart pieces (see ChartParts.hpp).
#include "problems/output/ChartParts.hpp"

#include <algorithm>
#include <cstdio>
#include <iterator>
#include <sstream>

#include "problems/output/Gnuplot.hpp"

namespace beamrotor {

namespace {

/// Line colours, in the order curves are drawn.
constexpr const char* kColours[] = {"#1f4e9c", "#c0392b", "#2e8b57", "#8e44ad", "#d35400"};
constexpr int kColourCount = int(std::size(kColours));

}  // namespace

std::string colour(std::size_t i) {
  return std::string("linecolor rgb '") + kColours[i % kColourCount] + "'";
}

std::string colourValue(std::size_t i) {
  return std::string("0x") + (kColours[i % kColourCount] + 1);
}

std::string number(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6g", x);
  return buffer;
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
         " title " + captionText(caption) + " font ',13' margins " + fractionX(90) + "," +
         fractionX(width - double(rightMargin)) + "," + fractionY(60) + "," +
         fractionY(height - 60.0 - 20.0 * double(lines)) + " spacing " +
         fractionX(columns > 1 ? 100 : 0) + "," + fractionY(rows > 1 ? 75 : 0) + "\n";
}

}  // namespace beamrotor
