#include "problems/cli/StabilitySummary.hpp"

#include <cmath>

#include "problems/cli/Summary.hpp"

namespace beamrotor::cli {

void printBuckling(std::ostream& out, const AnalysisOutcome& a) {
  const BucklingResult& r = *resultOf<BucklingResult>(a);
  out << "buckling analysis '" << a.name << "': load factors (critical load = factor x the "
      << "deck's loads)\n";
  for (std::size_t i = 0; i < r.modes.size(); ++i)
    out << "  mode " << i + 1 << ": " << formatValue(r.modes[i].factor) << "\n";
  for (std::size_t i = 0; i < r.reversed.size(); ++i)
    out << "  mode " << r.modes.size() + i + 1 << ": " << formatValue(r.reversed[i].factor)
        << " (load reversed)\n";
}

void printSecondOrder(std::ostream& out, const AnalysisOutcome& a) {
  if (!resultOf<SecondOrderResult>(a)) return;
  const SecondOrderResult& r = *resultOf<SecondOrderResult>(a);
  out << "  second order (equilibrium in the deformed state, " << r.iterations
      << (r.iterations == 1 ? " iteration" : " iterations") << "): lowest buckling factor "
      << (std::isfinite(r.criticalFactor) ? formatValue(r.criticalFactor) : "none (no compression)")
      << "\n    amplification against first order (largest second-order value over the "
         "first-order one): moment "
      << formatValue(r.momentAmplification) << ", normal stress "
      << formatValue(r.stressAmplification) << ", displacement "
      << formatValue(r.displacementAmplification) << ", rotation "
      << formatValue(r.rotationAmplification) << "\n";
}

}  // namespace beamrotor::cli
