#include "problems/cli/TorsionSummary.hpp"

#include <cstdio>
#include <numbers>
#include <string>

namespace beamrotor::cli {

namespace {
constexpr double kSummaryRpm = 60 / (2 * std::numbers::pi);

std::string trainFigure(const char* format, double v) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, format, v);
  return buffer;
}
}  // namespace

void printTrain(std::ostream& out, const TorsionOutcome& t) {
  out << "    speeds over shaft '" << t.reference << "':";
  for (std::size_t i = 0; i < t.shafts.size(); ++i)
    out << " " << t.shafts[i] << " " << trainFigure("%.6g", t.speedRatios[i]);
  out << "\n";
  if (!t.orders.empty()) {
    out << "    interference " << trainFigure("%.6g", t.speedFrom * kSummaryRpm) << " to "
        << trainFigure("%.6g", t.speedTo * kSummaryRpm) << " rpm: " << t.crossings.size() << " crossings\n";
    for (const TorsionCrossing& c : t.crossings)
      out << "      order " << trainFigure("%g", c.order) << " x mode " << c.mode << " ("
          << trainFigure("%.5g", c.frequencyHz) << " Hz) at " << trainFigure("%.6g", c.speed * kSummaryRpm) << " rpm\n";
  }
  if (!t.excitation.empty()) {
    out << "    harmonic torques:";
    for (const HarmonicTorque& h : t.excitation)
      out << " " << h.at.name() << " order " << trainFigure("%g", h.order) << " "
          << trainFigure("%.5g", h.amplitude) << " N m;";
    out << "\n";
  }
  if (t.atSpeed) {
    out << "    steady response at " << trainFigure("%.6g", t.atSpeed->speed * kSummaryRpm)
        << " rpm (peak over a revolution):\n";
    for (const ResponseTrace& r : t.atSpeed->torques)
      out << "      torque " << r.name << ": " << trainFigure("%.5g", r.peak) << " N m\n";
    for (const ResponseTrace& r : t.atSpeed->twists)
      out << "      twist " << r.name << ": " << trainFigure("%.5g", r.peak) << " rad\n";
  }
}

}  // namespace beamrotor::cli
