// The grid3d benchmark: a pinned square grillage of 3D frame elements under a load at every
// node (StandardModels.hpp). Exact references, independent of the discretisation:
//  - global equilibrium: the vertical reactions sum to the total load (to round-off);
//  - the square's symmetry (its dihedral group D4): the deflection field is unchanged by the
//    mirrors x -> L - x, y -> L - y and x <-> y, so every node deflects as its images do;
//  - modes of the E representation of D4 come in degenerate pairs (the second and third).
#include <cmath>
#include <stdexcept>

#include "fem/modal/Modal.hpp"
#include "fem/solvers/HeapReserve.hpp"
#include "fem/static/Static.hpp"
#include "fem/timing/Stopwatch.hpp"
#include "problems/bench/BenchKinds.hpp"
#include "problems/bench/StandardModels.hpp"

namespace beamrotor {

namespace {

/// The deflection field's size and its departure from the square's symmetry.
struct Deflection {
  double largest = 0;    ///< largest |uz| (m)
  double asymmetry = 0;  ///< largest |uz(p) - uz(image of p)| over the three mirrors / largest
};

Deflection deflection(const GridBenchModel& grid, const NodalField& u) {
  const int uz = dofIndex(Dof::uz), last = grid.side - 1;
  Deflection d;
  double worst = 0;
  for (int j = 0; j <= last; ++j)
    for (int i = 0; i <= last; ++i) {
      const int p = grid.nodeAt(i, j);
      if (p < 0) continue;
      d.largest = std::max(d.largest, std::abs(u(p, uz)));
      for (const int image :
           {grid.nodeAt(last - i, j), grid.nodeAt(i, last - j), grid.nodeAt(j, i)})
        worst = std::max(worst, std::abs(u(p, uz) - u(image, uz)));
    }
  d.asymmetry = d.largest > 0 ? worst / d.largest : 0;
  return d;
}

double verticalReaction(const StaticResult& s) {
  double sum = 0;
  for (const ReactionComponent& r : s.reactions)
    if (r.dof == Dof::uz) sum += r.value;
  return sum;
}

}  // namespace

BenchReport benchGrid(const BenchOptions& options) {
  const int bays = options.dofs > 0 ? closestSize(options.dofs, gridFreeDofs)
                                    : closestSize(options.elements, gridElements);
  const int modes = modesOrDefault(options, 10);
  BenchReport report;
  BenchSamples samples;
  double reaction = 0, totalLoad = 0, centreW = 0, pairSplit = 0;
  Deflection w;
  for (int run = 0; run < std::max(1, options.repeat); ++run) {
    prepareMemory(options, estimatedStaticBytes(gridElements(bays), 6));
    Stopwatch clock;
    const GridBenchModel grid = gridBenchModel(bays);
    const double build = clock.lap();
    const StaticResult s = solveStatic(*grid.model);
    samples.addStatic(build, s, report);
    reaction = verticalReaction(s);
    totalLoad = grid.totalLoad;
    w = deflection(grid, s.displacement);
    const int centre = grid.nodeAt(grid.side / 2, grid.side / 2);  // -1 for odd bay counts
    if (centre >= 0) centreW = s.displacement(centre, dofIndex(Dof::uz));
    if (modes > 0) {
      const ModalResult m = solveModes(*grid.model, {modes, 0});
      samples.addModal(m.time.total);
      report.warnings = m.warnings;
      report.frequenciesHz.clear();
      for (const Mode& mode : m.modes) report.frequenciesHz.push_back(mode.frequencyHz);
      if (m.modes.size() >= 3)
        pairSplit = std::abs(m.modes[2].frequencyHz / m.modes[1].frequencyHz - 1);
    }
    if (run == 0) exportIfAsked(options, *grid.model, report);
  }
  report.median = samples.medians();
  report.relErrorStatic = std::abs(reaction / totalLoad - 1);
  report.figures = {{"/bays", double(bays), "bays per side"},
                    {"/reaction_z", reaction, "sum of vertical reactions (N)"},
                    {"/total_load", totalLoad, "total load (N)"},
                    {"/largest_w", w.largest, "largest |uz| (m)"},
                    {"/symmetry_error", w.asymmetry, "largest asymmetry of uz (relative)"}};
  if (bays % 2 == 0) report.figures.push_back({"/centre_w", centreW, "centre deflection uz (m)"});
  if (report.frequenciesHz.size() >= 3)
    report.figures.push_back(
        {"/modal/pair_split", pairSplit, "f3 / f2 - 1 (a degenerate pair by symmetry)"});
  return report;
}

}  // namespace beamrotor
