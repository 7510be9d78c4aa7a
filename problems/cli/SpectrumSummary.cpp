#include "problems/cli/SpectrumSummary.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "fem/assembly/MemberExtrema.hpp"
#include "problems/cli/Summary.hpp"
#include "problems/output/structure/NoiseFloor.hpp"
#include "problems/output/structure/SpectrumOutput.hpp"

namespace beamrotor::cli {

void printSpectrum(std::ostream& out, const AnalysisOutcome& a, const ResponseSpectrumResult& r,
                   const Model& model, const OutputUnits& units) {
  // Each column in the user's unit of its quantity where set, else in its own.
  const OutputUnits::Shown hz = units.valueIn("Hz", {1, "Hz"});
  const OutputUnits::Shown period = units.valueIn("s", {1, "s"});
  const OutputUnits::Shown sa = units.valueIn("m/s^2", {1, "m/s^2"});
  const OutputUnits::Shown kg = units.valueIn("kg", {1, "kg"});
  out << a.type << " analysis '" << a.name << "' (" << r.modal.modes.size() << " modes, "
      << (r.rule == ModalRule::cqc ? "CQC" : "SRSS") << ", directions";
  for (int d : r.directions) out << " " << directionName(d);
  if (r.directions.size() > 1)
    out << " by " << (r.directional == DirectionalRule::srss ? "SRSS" : "100/30 %");
  out << ")\n    spectrum: " << r.spectrum.describe() << "\n";
  if (r.verticalSpectrum)
    out << "    vertical spectrum (along " << directionName(r.vertical)
        << "): " << r.verticalSpectrum->describe() << "\n";
  out << "    mode  " << padded("f [" + hz.unit + "]", 12) << padded("T [" + period.unit + "]", 12)
      << padded("Sa [" + sa.unit + "]", 12);
  for (int d : r.directions)
    out << padded(std::string("m_") + directionName(d) + " [" + kg.unit + "]", 13)
        << padded(std::string("sum ") + directionName(d), 8);
  out << "\n";
  std::array<double, 3> sum{};
  for (std::size_t j = 0; j < r.modal.modes.size(); ++j) {
    const Mode& m = r.modal.modes[j];
    out << "    " << padded(std::to_string(j + 1), 6)
        << padded(formatValue(m.frequencyHz * hz.factor), 12)
        << padded(formatValue(2 * std::numbers::pi / std::sqrt(m.eigenvalue) * period.factor),
                  12)
        << padded(formatValue(r.spectralAcceleration[j] * sa.factor), 12);
    for (int d : r.directions) {
      sum[d] += m.effectiveMass[d];
      char percent[16];
      std::snprintf(percent, sizeof percent, "%.1f %%", 100 * sum[d] / r.modal.totalMass[d]);
      // A mode that does not move the mass along d shows 0, not its round-off (NoiseFloor.hpp).
      const double shown =
          zeroAtOrBelow(m.effectiveMass[d], kNegligibleShare * r.modal.totalMass[d]);
      out << padded(formatValue(shown * kg.factor), 13) << padded(percent, 8);
    }
    out << "\n";
  }
  const PeakResponse& p = r.combined;
  out << "    combined peaks: base force";
  const double base = std::max({p.baseForce[0], p.baseForce[1], p.baseForce[2]});
  const auto baseForces = [&](const PeakResponse& peak) {
    for (int d = 0; d < 3; ++d)
      out << " " << directionName(d) << " "
          << valueText(peak.baseForce[d] > 1e-9 * base ? peak.baseForce[d] : 0.0, "N", units);
    out << "\n";
  };
  baseForces(p);
  if (r.combinations.size() > 1)
    for (const DirectionalCombination& c : r.combinations) {
      out << "    combination " << c.name << ": base force";
      baseForces(c.peak);
    }
  for (int k = 0; k < 3; ++k)
    if (p.displacement.rows() > 0 &&
        p.displacement.col(k).maxCoeff() > 1e-9 * p.displacement.leftCols(3).maxCoeff()) {
      int node = 0;
      const double largest = p.displacement.col(k).maxCoeff(&node);
      const std::string name = model.nameOf(node);
      out << "    largest " << dofName(kAllDofs[k]) << " " << valueText(largest, "m", units)
          << " at "
          << (name.empty() ? "node " + std::to_string(node) : name) << "\n";
    }
  // Components below 1e-9 of the largest of their kind (forces, moments) are round-off of a
  // zero: left out, or shown as 0.
  std::array<double, 2> largest{};  // forces, moments
  for (const ReactionComponent& c : p.reactions)
    largest[isRotation(c.dof)] = std::max(largest[isRotation(c.dof)], c.value);
  for (std::size_t i = 0; i < p.reactions.size(); ++i) {
    const ReactionComponent& c = p.reactions[i];
    if (!(c.value > 1e-9 * largest[isRotation(c.dof)])) continue;
    out << "    reaction " << c.support << " " << dofName(c.dof) << " "
        << valueText(c.value, isRotation(c.dof) ? "N m" : "N", units);
    if (r.combinations.size() > 1)
      out << " (" << r.combinations[governingCombination(r, [i](const PeakResponse& q) {
                       return q.reactions[i].value;
                     })].name
          << " governs)";
    out << "\n";
  }
  const auto isMoment = [](ForceComponent c) {
    return c == ForceComponent::T || c == ForceComponent::My || c == ForceComponent::Mz;
  };
  std::array<double, 2> largestResultant{};
  for (const BeamStation& s : p.stations)
    for (ForceComponent c : kForceComponents)
      largestResultant[isMoment(c)] =
          std::max(largestResultant[isMoment(c)], componentOf(s.forces, c));
  for (const auto& [name, elements] : model.members()) {
    out << "    member " << padded(name, 12);
    for (ForceComponent c : kForceComponents) {
      const double peak = memberPeak(p, elements, c);
      out << " " << componentName(c) << " "
          << valueText(peak > 1e-9 * largestResultant[isMoment(c)] ? peak : 0.0,
                       isMoment(c) ? "N m" : "N", units);
    }
    out << "\n";
  }
}

void printBaseMotion(std::ostream& out, const AnalysisOutcome& a, const BaseMotionResult& r,
                     const Model& model, const OutputUnits& units) {
  const BaseMotionOptions& o = r.options;
  out << a.type << " analysis '" << a.name << "' (ground along " << directionName(o.direction)
      << ", " << (o.displacement > 0 ? valueText(o.displacement, "m", units)
                                     : valueText(o.acceleration, "m/s^2", units))
      << ", " << r.points.size() << " frequencies, "
      << (o.method == BaseMotionMethod::modal ? std::to_string(r.modal.modes.size()) + " modes"
                                              : std::string("direct"))
      << ")\n";
  double force = 0;
  for (const BaseMotionPoint& p : r.points) force = std::max(force, std::abs(p.baseForce));
  for (const auto& [name, node] : model.namedNodes()) {
    double T = 0, at = 0, relative = 0;
    for (const BaseMotionPoint& p : r.points) {
      relative = std::max(relative, std::abs(p.relative(node, o.direction)));
      if (p.transmissibility(node, o.direction) > T) {
        T = p.transmissibility(node, o.direction);
        at = p.frequencyHz;
      }
    }
    if (relative == 0) continue;  // moves with the ground
    out << "    " << padded(name, 12) << "transmissibility max " << formatValue(T) << " at "
        << valueText(at, "Hz", units) << ", relative displacement max "
        << valueText(relative, "m", units) << "\n";
  }
  out << "    base force max " << valueText(force, "N", units) << "\n";
}

}  // namespace beamrotor::cli
