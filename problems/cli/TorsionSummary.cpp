#include "problems/cli/TorsionSummary.hpp"

#include <cstdio>
#include <numbers>
#include <string>

#include "problems/cli/Summary.hpp"

namespace beamrotor::cli {

namespace {
constexpr double kSummaryRpm = 60 / (2 * std::numbers::pi);

std::string trainFigure(const char* format, double v) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, format, v);
  return buffer;
}
}  // namespace

void printTrain(std::ostream& out, const TorsionOutcome& t, const OutputUnits& units) {
  // Speeds in rpm, frequencies in Hz, torques in N m and twists in rad unless the user set
  // their quantities.
  const auto speed = [&](double radPerSecond) {
    return valueText(radPerSecond * kSummaryRpm, "rpm", units);
  };
  out << "    speeds over shaft '" << t.reference << "':";
  for (std::size_t i = 0; i < t.shafts.size(); ++i)
    out << " " << t.shafts[i] << " " << trainFigure("%.6g", t.speedRatios[i]);
  out << "\n";
  if (!t.orders.empty()) {
    out << "    interference " << speed(t.speedFrom) << " to " << speed(t.speedTo) << ": "
        << t.crossings.size() << " crossings\n";
    for (const TorsionCrossing& c : t.crossings)
      out << "      order " << trainFigure("%g", c.order) << " x mode " << c.mode << " ("
          << valueText(c.frequencyHz, "Hz", units) << ") at " << speed(c.speed) << "\n";
  }
  if (!t.excitation.empty()) {
    out << "    harmonic torques:";
    for (const HarmonicTorque& h : t.excitation)
      out << " " << h.at.name() << " order " << trainFigure("%g", h.order) << " "
          << valueText(h.amplitude, "N m", units) << ";";
    out << "\n";
  }
  if (t.atSpeed) {
    out << "    steady response at " << speed(t.atSpeed->speed) << " (peak over a revolution):\n";
    for (const ResponseTrace& r : t.atSpeed->torques)
      out << "      torque " << r.name << ": " << valueText(r.peak, "N m", units) << "\n";
    for (const ResponseTrace& r : t.atSpeed->twists)
      out << "      twist " << r.name << ": " << valueText(r.peak, "rad", units) << "\n";
  }
}

}  // namespace beamrotor::cli
