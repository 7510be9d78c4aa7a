#include "problems/cli/CrankSummary.hpp"

#include <cmath>
#include <numbers>

#include "problems/cli/Summary.hpp"

namespace beamrotor::cli {

namespace {

/// "cancels" when the cranks' phases leave less than 1e-9 of one crank's amplitude.
std::string crankBalanceText(double oneCrank, double allCranks, const OutputUnits& units) {
  if (oneCrank > 0 && allCranks <= 1e-9 * oneCrank) return "cancels";
  return valueText(allCranks, "N", units);
}

}  // namespace

void printCrankSlider(std::ostream& out, const AnalysisOutcome& a, const OutputUnits& units) {
  const CrankSliderOutcome& c = *resultOf<CrankSliderOutcome>(a);
  const crank::Geometry& g = c.input.geometry;
  const auto shown = [&](double value, const char* unit) { return valueText(value, unit, units); };
  // The crank speed in rpm with rad/s beside it, or in the user's speed unit alone.
  std::string speed = shown(c.input.speed * 30 / std::numbers::pi, "rpm");
  if (!units.sets("rpm")) speed += " (" + formatValue(c.input.speed) + " rad/s)";
  out << "crank-slider analysis '" << a.name << "': r = " << shown(g.r, "m")
      << ", l = " << shown(g.l, "m") << ", lambda = " << formatValue(c.lambda) << ", " << speed
      << ", " << c.input.phases.size() << " crank(s)\n"
      << "    slider: v_max = " << shown(c.vMax, "m/s") << ", v_mean = " << shown(c.vMean, "m/s")
      << " (ratio " << formatValue(c.vMax / c.vMean) << "), a_max = " << shown(c.aMax, "m/s^2")
      << "\n"
      << "    rod: beta_max = " << shown(c.betaMax, "rad") << ", angular velocity amplitude "
      << shown(c.betaDotMax, "rad/s") << ", angular acceleration amplitude "
      << shown(c.betaDDotMax, "rad/s^2") << " (first order "
      << formatValue(c.betaDDotMaxFirstOrder) << ")\n"
      << "    harmonics of the slider acceleration: A2 = " << formatValue(c.series.A2)
      << ", A4 = " << formatValue(c.series.A4) << ", A6 = " << formatValue(c.series.A6) << "\n";
  if (c.reduced) {
    out << "    reduced masses: rotating " << shown(c.reduced->rotating, "kg")
        << ", reciprocating " << shown(c.reduced->reciprocating, "kg") << "\n"
        << "    inertia force, one crank: 1st harmonic " << shown(c.harmonics[0], "N")
        << ", 2nd " << shown(c.harmonics[1], "N") << ", rotating "
        << shown(c.rotatingForce, "N") << "\n"
        << "    over the " << c.input.phases.size() << " cranks: 1st harmonic "
        << crankBalanceText(c.harmonics[0], c.cranksHarmonics[0], units) << ", 2nd "
        << crankBalanceText(c.harmonics[1], c.cranksHarmonics[1], units) << ", 4th "
        << crankBalanceText(c.harmonics[2], c.cranksHarmonics[2], units) << ", 6th "
        << crankBalanceText(c.harmonics[3], c.cranksHarmonics[3], units) << ", rotating "
        << crankBalanceText(c.rotatingForce, c.cranksRotating, units) << "\n"
        << "    rod inertia moment amplitude " << shown(c.momentMax, "N m") << " (first order "
        << shown(c.momentMaxFirstOrder, "N m") << ")\n";
  }
  if (c.delivery > 0)
    out << "    theoretical delivery " << formatValue(c.delivery) << " m^3/s ("
        << formatValue(c.delivery * 60e3) << " L/min)\n";
}

}  // namespace beamrotor::cli
