// The rotor benchmark: a Campbell diagram of 50 speeds for a shaft with three disks on two
// isotropic bearings (StandardModels.hpp). Exact references:
//  - statics under self weight: the bearing forces k (uy_A + uy_B) balance the weight (global
//    equilibrium, to round-off);
//  - at rest the gyroscopic terms vanish and the two bending planes decouple, so the rotor's
//    natural frequencies are those of the same shaft as a planar model, each twice; the twin
//    is solved by the symmetric Lanczos modal analysis, a second method.
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "fem/modal/Modal.hpp"
#include "fem/rotor/RotorCampbell.hpp"
#include "fem/solvers/HeapReserve.hpp"
#include "fem/static/Static.hpp"
#include "fem/timing/Stopwatch.hpp"
#include "problems/bench/BenchKinds.hpp"
#include "problems/bench/StandardModels.hpp"

namespace beamrotor {

namespace {

constexpr int kSpeeds = 50;
constexpr double kTopSpeed = 10000 * 2 * 3.141592653589793 / 60;  // 10000 rpm in rad/s

/// Free dofs of the rotor with 4 q elements: 4 per node.
long long rotorFreeDofs(int quarters) {
  return 4LL * (4 * quarters + 1);
}

std::vector<double> campbellSpeeds() {
  std::vector<double> speeds(kSpeeds);
  for (int s = 0; s < kSpeeds; ++s) speeds[s] = kTopSpeed * s / (kSpeeds - 1);
  return speeds;
}

/// Largest relative difference between the rotor's frequencies at rest (ascending, in pairs)
/// and its planar twin's (each standing for a pair).
double twinError(const std::vector<double>& rotorHz, int elements) {
  const int pairs = int(rotorHz.size() + 1) / 2;
  const ModalResult twin = solveModes(*rotorPlanarTwin(elements), {pairs, 0});
  double worst = 0;
  for (std::size_t i = 0; i < rotorHz.size(); ++i)
    worst = std::max(worst, std::abs(rotorHz[i] / twin.modes[i / 2].frequencyHz - 1));
  return worst;
}

}  // namespace

BenchReport benchRotor(const BenchOptions& options) {
  const int elements =
      options.dofs > 0 ? 4 * closestSize(options.dofs, rotorFreeDofs) : options.elements;
  if (elements < 4) throw std::invalid_argument("bench rotor needs at least 4 elements");
  const int modes = modesOrDefault(options, 12);
  const std::vector<double> speeds = campbellSpeeds();
  BenchReport report;
  BenchSamples samples;
  double bearingForce = 0, weight = 0;
  int symbolicAnalyses = 0;
  for (int run = 0; run < std::max(1, options.repeat); ++run) {
    prepareMemory(options, estimatedStaticBytes(elements, 4));
    Stopwatch clock;
    const RotorBenchModel rotor = rotorBenchModel(elements);
    const double build = clock.lap();
    const StaticResult s = solveStatic(*rotor.model);
    samples.addStatic(build, s, report);
    report.elements = rotor.elements;  // shaft elements (the disks and bearings not counted)
    bearingForce = 0;
    for (int node : rotor.bearingNodes)
      bearingForce -= rotor.bearingStiffness * s.displacement(node, dofIndex(Dof::uy));
    weight = rotor.weight;
    if (modes > 0) {
      RotorOptions ro;
      ro.modes = modes;
      clock.lap();
      const CampbellResult c = solveCampbell(*rotor.model, speeds, ro);
      samples.addModal(clock.lap());
      symbolicAnalyses = c.symbolicAnalyses;
      report.frequenciesHz.clear();
      for (const auto& line : c.lines) report.frequenciesHz.push_back(line[0].naturalFrequencyHz);
      std::sort(report.frequenciesHz.begin(), report.frequenciesHz.end());
    }
    if (run == 0) exportIfAsked(options, *rotor.model, report);
  }
  report.median = samples.medians();
  report.relErrorStatic = std::abs(bearingForce / weight - 1);
  report.figures = {{"/bearing_force_y", bearingForce, "sum of bearing forces (N)"},
                    {"/weight", weight, "weight (N)"}};
  if (!report.frequenciesHz.empty()) {
    report.figures.push_back({"/campbell/speeds", double(speeds.size()), "Campbell speeds"});
    report.figures.push_back({"/campbell/modes", double(modes), "Campbell lines"});
    report.figures.push_back({"/campbell/top_speed_rad_s", kTopSpeed, "top speed (rad/s)"});
    report.figures.push_back({"/campbell/symbolic_analyses", double(symbolicAnalyses),
                              "symbolic factorisations in the sweep"});
    report.figures.push_back({"/modal/rel_error_planar_twin",
                              twinError(report.frequenciesHz, elements),
                              "frequencies at rest vs planar twin (rel.)"});
  }
  return report;
}

}  // namespace beamrotor
