// The planar benchmark: a long continuous beam pinned at every span end (StandardModels.hpp).
// Exact references: the midspan deflection of an interior span, q s^4 / (384 E I) (a
// clamped-clamped span by symmetry; Hermite elements with the consistent load vector are
// nodally exact), and the simply supported span frequency pi / (2 s^2) sqrt(E I / (rho A)).
#include <cmath>

#include "fem/modal/Modal.hpp"
#include "fem/solvers/HeapReserve.hpp"
#include "fem/static/Static.hpp"
#include "fem/timing/Stopwatch.hpp"
#include "problems/bench/BenchKinds.hpp"
#include "problems/bench/StandardModels.hpp"

namespace beamrotor {

namespace {

constexpr int kElementsPerSpan = 10;

/// Free dofs of the model with `spans` spans: 3 per node less 2 per span end.
long long planarFreeDofs(int spans) {
  return 3LL * (kElementsPerSpan * spans + 1) - 2LL * (spans + 1);
}

}  // namespace

BenchReport benchPlanar(const BenchOptions& options) {
  const int elements = options.dofs > 0
                           ? kElementsPerSpan * closestSize(options.dofs, planarFreeDofs)
                           : options.elements;
  if (elements < kElementsPerSpan)
    throw std::invalid_argument("bench planar needs at least 10 elements");
  const int modes = modesOrDefault(options, 10);
  BenchReport report;
  BenchSamples samples;
  double midspanW = 0, exactMidspanW = 0, exactLowestHz = 0;
  for (int run = 0; run < std::max(1, options.repeat); ++run) {
    prepareMemory(options, estimatedStaticBytes(elements, 3));
    Stopwatch clock;
    const PlanarBenchModel bench = planarBenchModel(elements);
    const double build = clock.lap();
    const StaticResult s = solveStatic(*bench.model);
    samples.addStatic(build, s, report);
    midspanW = s.displacement(bench.midspanNode, dofIndex(Dof::uy));
    exactMidspanW = bench.exactMidspanW;
    exactLowestHz = bench.exactLowestHz;
    if (modes > 0) {
      const ModalResult m = solveModes(*bench.model, {modes, 0});
      samples.addModal(m.time.total);
      report.warnings = m.warnings;
      report.frequenciesHz.clear();
      for (const Mode& mode : m.modes) report.frequenciesHz.push_back(mode.frequencyHz);
    }
    if (run == 0) exportIfAsked(options, *bench.model, report);
  }
  report.median = samples.medians();
  report.relErrorStatic = std::abs(midspanW / exactMidspanW - 1);
  report.figures = {{"/midspan_w", midspanW, "midspan w (m)"},
                    {"/exact_midspan_w", exactMidspanW, "q s^4 / (384 E I) (m)"}};
  if (!report.frequenciesHz.empty()) {
    report.figures.push_back(
        {"/modal/exact_lowest_hz", exactLowestHz, "simply supported span frequency (Hz)"});
    report.figures.push_back({"/modal/rel_error_lowest",
                              std::abs(report.frequenciesHz[0] / exactLowestHz - 1),
                              "f1 above it (discrete model: 6.7e-6)"});
  }
  return report;
}

}  // namespace beamrotor
