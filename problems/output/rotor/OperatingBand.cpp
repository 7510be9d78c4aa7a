// The operating range and its API 684 margins on a chart (see OperatingBand.hpp).
#include "problems/output/rotor/OperatingBand.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "problems/output/files/ChartParts.hpp"
#include "problems/output/files/Gnuplot.hpp"
#include "problems/output/rotor/RotorTables.hpp"

namespace beamrotor {

namespace {

constexpr const char* kRangeFill = "#f0b429";   // amber: the operating range
constexpr const char* kMarginFill = "#fbe3a6";  // light amber: the margins around it

/// Widens the band's margin on the side of a critical at `rpm` with factor AF.
void widenMargins(OperatingBand& band, double rpm, double af) {
  if (rpm < band.minRpm)
    band.marginBelow = std::max(band.marginBelow, requiredSeparationMargin(af, false));
  else if (rpm > band.maxRpm)
    band.marginAbove = std::max(band.marginAbove, requiredSeparationMargin(af, true));
}

/// The range in rpm, no margins yet.
OperatingBand unmarginedBand(const OperatingRange& range) {
  OperatingBand band;
  band.minRpm = rpmOf(range.minimum);
  band.maxRpm = rpmOf(range.maximum);
  return band;
}

std::string rectangle(int object, double from, double to, const char* fill) {
  return "  set object " + std::to_string(object) + " rectangle from first " + number(from) +
         ", graph 0 to first " + number(to) + ", graph 1 behind fillcolor rgb '" + fill +
         "' fillstyle solid 1.0 noborder\n";
}

}  // namespace

OperatingBand bandOfCriticalSpeeds(const OperatingRange& range,
                                   const std::vector<CriticalSpeed>& critical) {
  OperatingBand band = unmarginedBand(range);
  for (const CriticalSpeed& c : critical)
    widenMargins(band, c.rpm,
            c.dampingRatio > 0 ? 1 / (2 * c.dampingRatio) : std::numeric_limits<double>::infinity());
  return band;
}

OperatingBand bandOfPeaks(const OperatingRange& range,
                          const std::vector<std::vector<ResponsePeak>>& peaks) {
  OperatingBand band = unmarginedBand(range);
  for (const auto& point : peaks)
    for (const ResponsePeak& p : point)
      if (p.speed < range.minimum)
        band.marginBelow = std::max(band.marginBelow, p.requiredMargin);
      else if (p.speed > range.maximum)
        band.marginAbove = std::max(band.marginAbove, p.requiredMargin);
  return band;
}

BandCommands operatingBandCommands(const std::optional<OperatingBand>& band, double speedFactor,
                                   int firstObject) {
  BandCommands out;
  if (!band) return out;
  const double from = band->minRpm * speedFactor, to = band->maxRpm * speedFactor;
  const double low = from * (1 - band->marginBelow / 100);
  const double high = to * (1 + band->marginAbove / 100);
  if (band->marginBelow > 0) out.setup += rectangle(firstObject + 1, low, from, kMarginFill);
  if (band->marginAbove > 0) out.setup += rectangle(firstObject + 2, to, high, kMarginFill);
  out.setup += rectangle(firstObject, from, to, kRangeFill);
  const auto entry = [&](const char* fill, const std::string& title) {
    out.keyEntries += std::string(", \\\n       NaN with boxes fillstyle solid 1.0 noborder ") +
                      "fillcolor rgb '" + fill + "' title " + gnuplotText(title);
    out.titles.push_back(title);
  };
  entry(kRangeFill, "operating range");
  if (band->marginBelow > 0 || band->marginAbove > 0) entry(kMarginFill, "API margins");
  return out;
}

}  // namespace beamrotor
