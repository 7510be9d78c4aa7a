#include "problems/verify/OverRefinement.hpp"

#include <cmath>

#include "fem/static/Static.hpp"
#include "problems/run/OverRefinementWarning.hpp"
#include "problems/verify/VerifyModels.hpp"

namespace beamrotor::verify {

namespace {

constexpr double kRefinedBeamLength = 1.0, kSide = 0.02, kLoad = -1000.0;  // m, m, N/m

RefinementPoint solveMesh(int n) {
  Model model;
  const auto section = steelRectangle(kSide, kSide);
  const Line line = planarBeam(model, kRefinedBeamLength, section, n);
  // 1. The uniform load lumped to the nodes: q h at interior nodes, q h / 2 at the ends.
  const double h = kRefinedBeamLength / n;
  for (std::size_t i = 1; i < line.nodes.size(); ++i)
    model.addLoad({line.nodes[i], Dof::uy, kLoad * h * (i + 1 == line.nodes.size() ? 0.5 : 1)});
  // 2. Solve whatever the conditioning: the study wants to see round-off, not a refusal.
  StaticOptions options;
  options.singularRcond = 0;
  const StaticResult r = solveStatic(model, options);
  // 3. Against Euler-Bernoulli's w(L) = q L^4 / (8 E I) (Timoshenko and Gere, Mechanics of
  // Materials, table of cantilever deflections). Lumping drops the consistent end moments
  // q h^2 / 12 (Przemieniecki 1968, ch. 11); at interior nodes they cancel and at the root the
  // support takes them, so only the tip's is missing: its deflection M L^2 / (2 E I) makes the
  // discretisation error exactly h^2 / (3 L^2) = 1 / (3 N^2), and anything above it is round-off.
  const double exact = kLoad * std::pow(kRefinedBeamLength, 4) / (8 * section->EIz());
  RefinementPoint p;
  p.elements = n;
  p.error = std::abs(r.displacement(line.nodes.back(), 1) - exact) / std::abs(exact);
  p.discretisation = 1.0 / (3.0 * double(n) * double(n));
  p.rcond = r.rcond;
  p.seconds = r.time.total;
  p.warned = overRefinementWarning(model, r).has_value();
  return p;
}

}  // namespace

std::vector<RefinementPoint> overRefinementStudy(const std::vector<int>& elementCounts) {
  std::vector<RefinementPoint> points;
  for (int n : elementCounts) points.push_back(solveMesh(n));
  return points;
}

}  // namespace beamrotor::verify
