#include "problems/verify/FailureCharts.hpp"

#include <cmath>

#include "problems/verify/EigenCluster.hpp"
#include "problems/verify/FreeFreeShift.hpp"
#include "problems/verify/OverRefinement.hpp"
#include "problems/verify/PenaltySupport.hpp"
#include "problems/verify/ShearLocking.hpp"
#include "problems/verify/TimeStepStudy.hpp"

namespace beamrotor::verify {

namespace {

/// Half-decade points from `from` to `to` (both powers of ten).
std::vector<double> halfDecades(double from, double to) {
  std::vector<double> v;
  for (double x = from; x <= to * 1.0001; x *= std::sqrt(10.0)) v.push_back(x);
  return v;
}

/// The three Timoshenko elements' errors as series against x.
std::vector<StudySeries> lockingSeries(const std::vector<LockingPoint>& points,
                                       bool bySlenderness) {
  std::vector<StudySeries> s{{"linear, full integration (locks)", {}, {}},
                             {"linear, reduced integration", {}, {}},
                             {"interdependent interpolation (exact)", {}, {}}};
  for (const LockingPoint& p : points) {
    const double x = bySlenderness ? p.slenderness : p.elements;
    const double errors[3] = {p.fullIntegration, p.reducedIntegration, p.interdependent};
    for (int k = 0; k < 3; ++k) {
      s[k].x.push_back(x);
      s[k].y.push_back(std::max(errors[k], 1e-17));  // a log axis cannot show an exact zero
    }
  }
  return s;
}

StudyChart lockingBySlenderness() {
  StudyChart c{"shear_locking_slenderness",
               "Shear locking against slenderness (8 elements)",
               "The naive linear Timoshenko element with full integration loses the tip "
               "deflection of a tip-loaded cantilever as L/h grows (99.99 % off at L/h = 10^4), "
               "while reduced integration stays at its 1/(4n^2) discretisation error and the "
               "interdependent-interpolation element is exact to round-off.",
               "slenderness L/h",
               "relative error of the tip deflection",
               "",
               true,
               true,
               {}};
  std::vector<double> slenderness = halfDecades(10, 1e4);
  c.series = lockingSeries(lockingAgainstSlenderness(slenderness, 8), true);
  return c;
}

StudyChart lockingByMesh() {
  StudyChart c{"shear_locking_mesh",
               "Shear locking against the element count (L/h = 1000)",
               "Refining cures locking only very slowly (still 55 % off with 512 elements), "
               "whereas the reduced-integration element converges at order 2 and the "
               "interdependent element is exact on every mesh.",
               "elements",
               "relative error of the tip deflection",
               "",
               true,
               true,
               {}};
  c.series =
      lockingSeries(lockingAgainstElements(1000, {2, 4, 8, 16, 32, 64, 128, 256, 512}), false);
  return c;
}

StudyChart penalty() {
  StudyChart c{"penalty_joint",
               "Penalty joint against elimination",
               "A cantilever joined at midspan by springs of stiffness k: soft springs add their "
               "own compliance (3.75 EI/(k L^3)), stiff ones destroy the conditioning (rcond "
               "~ 1/k, dashed) until round-off dominates; eliminating the joint (a shared node) "
               "is exact to round-off at every scale.",
               "k / (EI/L^3)",
               "relative error of the tip deflection",
               "1 / rcond",
               true,
               true,
               {}};
  StudySeries error{"penalty springs", {}, {}}, modelling{"spring compliance 3.75/ratio", {}, {}},
      exact{"elimination (shared node)", {}, {}}, condition{"1 / rcond, penalty", {}, {}, true};
  const PenaltyPoint eliminated = eliminatedJoint();
  for (const PenaltyPoint& p : penaltyStudy(halfDecades(1e3, 1e16))) {
    error.x.push_back(p.stiffnessRatio);
    error.y.push_back(p.error);
    modelling.x.push_back(p.stiffnessRatio);
    modelling.y.push_back(p.modelling);
    exact.x.push_back(p.stiffnessRatio);
    exact.y.push_back(std::max(eliminated.error, 1e-17));
    condition.x.push_back(p.stiffnessRatio);
    condition.y.push_back(1 / p.rcond);
  }
  c.series = {error, modelling, exact, condition};
  return c;
}

StudyChart freeFreeShifts() {
  const ShiftStudy study = freeFreeShiftStudy(halfDecades(1e-8, 1e2));
  StudyChart c{"free_free_shift",
               "Shift-invert on a free-free beam",
               "At shift 0 the stiffness of a free-free beam is singular and the modal solver "
               "stops with a clear error (\"" +
                   study.zeroShiftError.substr(0, 160) +
                   "...\"); any negative shift works, the first elastic frequency staying at its "
                   "discretisation error and the rigid-body eigenvalues at round-off.",
               "-shift / lambda_1",
               "relative to lambda_1 / relative error",
               "",
               true,
               true,
               {}};
  StudySeries elastic{"error of the first elastic frequency", {}, {}},
      rigid{"rigid-body |lambda| / lambda_1", {}, {}};
  for (const ShiftPoint& p : study.points) {
    elastic.x.push_back(p.shiftRatio);
    elastic.y.push_back(p.elasticError);
    rigid.x.push_back(p.shiftRatio);
    rigid.y.push_back(std::max(p.rigidBody, 1e-17));
  }
  c.series = {elastic, rigid};
  return c;
}

StudyChart clusters() {
  StudyChart c{"eigenvalue_clusters",
               "Equal frequencies in two planes: vectors against subspaces",
               "A square beam has every bending frequency twice: the computed vectors are an "
               "arbitrary basis of each 2-D eigenspace (0.4 to 1.3 rad from the exact single-plane "
               "shapes, as ARPACK's start vector falls), while the largest principal angle between "
               "computed and exact "
               "eigenspaces is at round-off.",
               "mode pair n",
               "angle (rad)",
               "",
               false,
               true,
               {}};
  StudySeries vector{"first vector against the exact y-plane shape", {}, {}},
      subspace{"largest principal angle, 2-D eigenspaces", {}, {}};
  for (const ClusterPoint& p : eigenClusterStudy(3)) {
    vector.x.push_back(p.order);
    vector.y.push_back(p.vectorAngle);
    subspace.x.push_back(p.order);
    subspace.y.push_back(std::max(p.subspaceAngle, 1e-17));
  }
  c.series = {vector, subspace};
  return c;
}

StudyChart timeSteps() {
  StudyChart c{"central_difference_steps",
               "Central difference at 0.9 and 1.1 dt_crit",
               "Released from a 1 mm bend, a lumped-mass cantilever stepped by central "
               "difference keeps its amplitude at 0.9 dt_crit (dt_crit = 2/omega_max) and "
               "blows up exponentially at 1.1 dt_crit.",
               "step",
               "|tip deflection| (m)",
               "",
               false,
               true,
               {}};
  for (const TimeStepRun& r : timeStepStudy({0.9, 1.1}, 300)) {
    StudySeries s{"dt = " + std::to_string(r.stepFactor).substr(0, 3) + " dt_crit", {}, {}};
    for (std::size_t i = 0; i < r.tip.size(); ++i) {
      s.x.push_back(double(i));
      s.y.push_back(std::max(std::abs(r.tip[i]), 1e-12));
    }
    c.series.push_back(s);
  }
  return c;
}

StudyChart overRefinement(int largestMesh) {
  StudyChart c{"over_refinement",
               "Over-refinement of a cantilever",
               "The tip error of a uniformly loaded cantilever (load lumped to the nodes) follows "
               "its exact discretisation error 1/(3N^2) until round-off, growing with the "
               "condition estimate 1/rcond (dashed), takes over near a few hundred elements; "
               "past 10^4 elements the answer is percent-level wrong.",
               "elements N",
               "relative error of the tip deflection",
               "1 / rcond",
               true,
               true,
               {}};
  std::vector<int> meshes;
  for (double n = 10; n <= largestMesh * 1.0001; n *= std::sqrt(10.0))
    meshes.push_back(int(std::lround(n)));
  StudySeries error{"computed", {}, {}}, discretisation{"discretisation 1/(3N^2)", {}, {}},
      condition{"1 / rcond", {}, {}, true};
  for (const RefinementPoint& p : overRefinementStudy(meshes)) {
    error.x.push_back(p.elements);
    error.y.push_back(p.error);
    discretisation.x.push_back(p.elements);
    discretisation.y.push_back(p.discretisation);
    condition.x.push_back(p.elements);
    condition.y.push_back(1 / p.rcond);
  }
  c.series = {error, discretisation, condition};
  return c;
}

}  // namespace

std::vector<StudyChart> failureCharts(const FailureChartOptions& options) {
  return {lockingBySlenderness(),
          lockingByMesh(),
          penalty(),
          freeFreeShifts(),
          clusters(),
          timeSteps(),
          overRefinement(options.largestMesh)};
}

}  // namespace beamrotor::verify
