#include "problems/cli/CrankSummary.hpp"

#include <cmath>
#include <numbers>

#include "problems/cli/Summary.hpp"

namespace beamrotor::cli {

namespace {

/// "cancels" when the cranks' phases leave less than 1e-9 of one crank's amplitude.
std::string crankBalanceText(double oneCrank, double allCranks) {
  if (oneCrank > 0 && allCranks <= 1e-9 * oneCrank) return "cancels";
  return formatValue(allCranks) + " N";
}

}  // namespace

void printCrankSlider(std::ostream& out, const AnalysisOutcome& a) {
  const CrankSliderOutcome& c = *resultOf<CrankSliderOutcome>(a);
  const crank::Geometry& g = c.input.geometry;
  out << "crank-slider analysis '" << a.name << "': r = " << formatValue(g.r)
      << " m, l = " << formatValue(g.l) << " m, lambda = " << formatValue(c.lambda) << ", "
      << formatValue(c.input.speed * 30 / std::numbers::pi) << " rpm ("
      << formatValue(c.input.speed) << " rad/s), " << c.input.phases.size() << " crank(s)\n"
      << "    slider: v_max = " << formatValue(c.vMax) << " m/s, v_mean = " << formatValue(c.vMean)
      << " m/s (ratio " << formatValue(c.vMax / c.vMean) << "), a_max = " << formatValue(c.aMax)
      << " m/s^2\n"
      << "    rod: beta_max = " << formatValue(c.betaMax) << " rad, angular velocity amplitude "
      << formatValue(c.betaDotMax) << " 1/s, angular acceleration amplitude "
      << formatValue(c.betaDDotMax) << " 1/s^2 (first order "
      << formatValue(c.betaDDotMaxFirstOrder) << ")\n"
      << "    harmonics of the slider acceleration: A2 = " << formatValue(c.series.A2)
      << ", A4 = " << formatValue(c.series.A4) << ", A6 = " << formatValue(c.series.A6) << "\n";
  if (c.reduced) {
    out << "    reduced masses: rotating " << formatValue(c.reduced->rotating)
        << " kg, reciprocating " << formatValue(c.reduced->reciprocating) << " kg\n"
        << "    inertia force, one crank: 1st harmonic " << formatValue(c.harmonics[0])
        << " N, 2nd " << formatValue(c.harmonics[1]) << " N, rotating "
        << formatValue(c.rotatingForce) << " N\n"
        << "    over the " << c.input.phases.size() << " cranks: 1st harmonic "
        << crankBalanceText(c.harmonics[0], c.cranksHarmonics[0]) << ", 2nd "
        << crankBalanceText(c.harmonics[1], c.cranksHarmonics[1]) << ", 4th "
        << crankBalanceText(c.harmonics[2], c.cranksHarmonics[2]) << ", 6th "
        << crankBalanceText(c.harmonics[3], c.cranksHarmonics[3]) << ", rotating "
        << crankBalanceText(c.rotatingForce, c.cranksRotating) << "\n"
        << "    rod inertia moment amplitude " << formatValue(c.momentMax) << " N m (first order "
        << formatValue(c.momentMaxFirstOrder) << ")\n";
  }
  if (c.delivery > 0)
    out << "    theoretical delivery " << formatValue(c.delivery) << " m^3/s ("
        << formatValue(c.delivery * 60e3) << " L/min)\n";
}

}  // namespace beamrotor::cli
