#include "fem/modal/ResponseSpectrum.hpp"

#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>

#include "fem/assembly/Assembly.hpp"
#include "fem/assembly/ReducedSystem.hpp"
#include "fem/assembly/RigidTies.hpp"
#include "fem/modal/Modal.hpp"
#include "fem/model/Loading.hpp"

namespace beamrotor {

namespace {

/// Every output quantity of one motion laid end to end, and back: the modal values are the
/// columns of one matrix, so each quantity is combined as one row.
class ResponseLayout {
 public:
  ResponseLayout(const Model& model, int stationsPerElement)
      : model_(model), dofs_(model), ties_(model, dofs_), perElement_(stationsPerElement) {
    if (!ties_.empty()) mass_ = SparseAssembler(model, dofs_).assemble(MatrixKind::mass);
  }

  /// The quantities of displacement field u (relative to the ground, no loads on the
  /// elements) of a mode of eigenvalue omega^2, with base force `base`.
  PeakResponse respond(const NodalField& u, double omega2, const std::array<double, 3>& base) const {
    PeakResponse r;
    r.displacement = u;
    const Eigen::VectorXd full = fromNodalField(dofs_, u);
    Eigen::VectorXd reaction = constrainedElementForces(model_, dofs_, full, unloaded_);
    if (!ties_.empty()) {
      // A fixed master also holds what its ties hold their followers with: at each follower,
      // its elements' forces less the inertia omega^2 M u the modal peak stands for.
      Eigen::VectorXd residual = elementForces(model_, dofs_, full, unloaded_);
      residual.head(dofs_.freeCount()) -= omega2 * (mass_ * full.head(dofs_.freeCount()));
      addTiedReactions(ties_.tied(), dofs_, residual, reaction);
    }
    for (const Support& s : model_.supports())
      for (const PrescribedDof& p : s.dofs)
        r.reactions.push_back(
            {s.name, s.node, p.dof, reaction[dofs_.equation(s.node, p.dof) - dofs_.freeCount()]});
    r.elementForces = namedElementForces(model_, u);
    r.stations = recoverBeamFields({model_, u, &unloaded_}, perElement_);
    r.baseForce = base;
    return r;
  }

  static Eigen::VectorXd flatten(const PeakResponse& r) {
    std::vector<double> v(r.displacement.data(), r.displacement.data() + r.displacement.size());
    for (const ReactionComponent& c : r.reactions) v.push_back(c.value);
    for (const ReactionComponent& c : r.elementForces) v.push_back(c.value);
    for (const BeamStation& s : r.stations) {
      v.insert(v.end(), s.displacement.begin(), s.displacement.end());
      const SectionForces& f = s.forces;
      v.insert(v.end(), {f.N, f.Vy, f.Vz, f.T, f.My, f.Mz});
    }
    v.insert(v.end(), r.baseForce.begin(), r.baseForce.end());
    return Eigen::Map<const Eigen::VectorXd>(v.data(), Eigen::Index(v.size()));
  }

  /// `shape` (names, places) with the values of `v`, laid out as flatten() lays them.
  static PeakResponse unflatten(PeakResponse shape, const Eigen::VectorXd& v) {
    Eigen::Index i = 0;
    for (Eigen::Index k = 0; k < shape.displacement.size(); ++k)
      shape.displacement.data()[k] = v[i++];
    for (ReactionComponent& c : shape.reactions) c.value = v[i++];
    for (ReactionComponent& c : shape.elementForces) c.value = v[i++];
    for (BeamStation& s : shape.stations) {
      for (double& d : s.displacement) d = v[i++];
      SectionForces& f = s.forces;
      for (double* x : {&f.N, &f.Vy, &f.Vz, &f.T, &f.My, &f.Mz}) *x = v[i++];
      s.stress = s.shear = 0;
    }
    for (double& b : shape.baseForce) b = v[i++];
    return shape;
  }

 private:
  const Model& model_;
  DofMap dofs_;
  TieReduction ties_;
  SparseMatrix mass_;  ///< free-free, made only with ties
  int perElement_;
  Loading unloaded_;
};

}  // namespace

const char* directionName(int d) {
  static constexpr const char* names[] = {"x", "y", "z"};
  return names[d];
}

std::array<double, 3> ResponseSpectrumResult::capturedFraction() const {
  std::array<double, 3> f{};
  for (int d = 0; d < 3; ++d) {
    if (modal.totalMass[d] <= 0) continue;
    for (const Mode& m : modal.modes) f[d] += m.effectiveMass[d];
    f[d] /= modal.totalMass[d];
  }
  return f;
}

double ResponseSpectrumResult::saOf(std::size_t j, int d) const {
  return verticalSpectrum && d == vertical ? verticalAcceleration.at(j)
                                           : spectralAcceleration.at(j);
}

namespace {

/// A warning for a mode outside a spectrum table (it reads the table's nearer end value).
void warnOutside(const DesignSpectrum& spectrum, std::size_t j, double T, double Sa,
                 const char* which, std::vector<std::string>& warnings) {
  if (spectrum.covers(T)) return;
  const std::vector<double> ends = spectrum.breakPeriods();
  std::ostringstream w;
  w << "mode " << j + 1 << " has the period " << T << " s, outside the " << which
    << "spectrum table's " << ends.front() << " to " << ends.back() << " s: it reads the table's "
    << (T < ends.front() ? "first" : "last") << " value, " << Sa
    << " m/s^2 (extend the table to be sure)";
  warnings.push_back(w.str());
}

/// "x + 0.3 y + 0.3 z" for the factors of `directions`; "SRSS" for that rule.
std::string combinationName(const std::vector<int>& directions, const std::vector<double>& factors,
                            DirectionalRule rule) {
  if (rule == DirectionalRule::srss) return directions.size() > 1 ? "SRSS" : directionName(directions.front());
  std::string name;
  for (std::size_t i = 0; i < directions.size(); ++i)
    if (factors[i] == 1) name = directionName(directions[i]);
  for (std::size_t i = 0; i < directions.size(); ++i)
    if (factors[i] != 1) {
      name += " + 0.3 ";
      name += directionName(directions[i]);
    }
  return name;
}

}  // namespace

ResponseSpectrumResult solveResponseSpectrum(const Model& model, const DesignSpectrum& spectrum,
                                             const ResponseSpectrumOptions& options) {
  ResponseSpectrumResult result;
  result.directions = options.directions;
  result.spectrum = spectrum;
  result.dampingRatio = options.dampingRatio;
  result.rule = options.rule;
  result.directional = options.directional;
  result.verticalSpectrum = options.verticalSpectrum;
  result.vertical = options.vertical;
  result.modal = solveModes(model, {options.modes, options.shift});
  result.warnings = result.modal.warnings;
  const ModalResult& modal = result.modal;
  for (int d : options.directions)
    if (modal.totalMass[d] <= 0)
      throw std::invalid_argument(std::string("no mass moves along ") + directionName(d) +
                                  ": the structure cannot be excited in that direction");

  // 1. Each mode's period and spectral acceleration.
  std::vector<double> omega;
  for (std::size_t j = 0; j < modal.modes.size(); ++j) {
    const Mode& mode = modal.modes[j];
    if (!(mode.eigenvalue > 0)) {
      std::ostringstream why;
      why << "mode " << j + 1 << " has no positive frequency (omega^2 = " << mode.eigenvalue
          << "): a structure that moves with the ground as a rigid body has no response "
             "spectrum; support it";
      throw std::domain_error(why.str());
    }
    omega.push_back(std::sqrt(mode.eigenvalue));
    const double T = 2 * std::numbers::pi / omega.back();
    result.spectralAcceleration.push_back(spectrum.at(T));
    warnOutside(spectrum, j, T, result.spectralAcceleration.back(), "", result.warnings);
    if (result.verticalSpectrum) {
      result.verticalAcceleration.push_back(result.verticalSpectrum->at(T));
      warnOutside(*result.verticalSpectrum, j, T, result.verticalAcceleration.back(),
                  "vertical ", result.warnings);
    }
  }
  result.correlation = modalCorrelations(omega, options.dampingRatio, options.rule);

  // 2. Each direction: every mode's quantities as a column, combined row by row.
  const ResponseLayout layout(model, options.stationsPerElement);
  Eigen::MatrixXd perDirection;
  for (std::size_t di = 0; di < options.directions.size(); ++di) {
    const int d = options.directions[di];
    Eigen::MatrixXd columns;
    PeakResponse shape;
    for (std::size_t j = 0; j < modal.modes.size(); ++j) {
      const Mode& mode = modal.modes[j];
      const double Sa = result.saOf(j, d);
      const double amplitude = mode.participation[d] * Sa / mode.eigenvalue;
      // The inertia forces M phi Gamma_d Sa sum along k to Gamma_k Gamma_d Sa: what the ground
      // takes, springs to it included.
      std::array<double, 3> base{};
      for (int k = 0; k < 3; ++k) base[k] = mode.participation[k] * mode.participation[d] * Sa;
      PeakResponse r = layout.respond(mode.shape * amplitude, mode.eigenvalue, base);
      const Eigen::VectorXd q = ResponseLayout::flatten(r);
      if (j == 0) {
        columns.resize(q.size(), Eigen::Index(modal.modes.size()));
        shape = std::move(r);
      }
      columns.col(Eigen::Index(j)) = q;
    }
    const Eigen::VectorXd peak = combineModes(columns, result.correlation);
    if (di == 0) perDirection.resize(peak.size(), Eigen::Index(options.directions.size()));
    perDirection.col(Eigen::Index(di)) = peak;
    result.perDirection.push_back(ResponseLayout::unflatten(shape, peak));
  }
  for (const std::vector<double>& factors :
       directionalFactors(options.directions.size(), options.directional))
    result.combinations.push_back(
        {combinationName(options.directions, factors, options.directional), factors,
         ResponseLayout::unflatten(
             result.perDirection.front(),
             combineDirectionsAs(perDirection, factors, options.directional))});
  result.combined = ResponseLayout::unflatten(
      result.perDirection.front(), combineDirections(perDirection, options.directional));

  // 3. EN 1998-1 4.3.3.3.1(3): the modes taken should capture at least 90 % of the mass.
  const std::array<double, 3> captured = result.capturedFraction();
  for (int d : options.directions)
    if (captured[d] < 0.9) {
      std::ostringstream w;
      w << "the " << modal.modes.size() << " modes capture " << 100 * captured[d]
        << " % of the mass along " << directionName(d)
        << ", less than the 90 % EN 1998-1 4.3.3.3.1 asks: compute more modes";
      result.warnings.push_back(w.str());
    }
  return result;
}

}  // namespace beamrotor
