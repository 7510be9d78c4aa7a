#include "fem/static/OneWayMembers.hpp"

#include <cmath>
#include <set>
#include <sstream>
#include <stdexcept>

#include "fem/assembly/Recovery.hpp"
#include "fem/solvers/Errors.hpp"

namespace beamrotor {

namespace {

// As for the contacts (ActiveSet.cpp): a force or elongation within this fraction of the
// problem's scale is round-off of the solve, far below any physical one; at an exact switch
// point both choices give the same solution.
constexpr double kOneWaySwitchTolerance = 1e-9;

/// The single line element member `name` of `model` is, or -1 when the model has no such
/// member (a slack one left out).
int oneWayElementOf(const Model& model, const std::string& name) {
  for (const auto& [member, elements] : model.members())
    if (member == name) {
      if (elements.size() != 1 || !asLine(model.elements().at(elements[0])))
        throw std::invalid_argument("member '" + name +
                                    "' acts one way only, so it must be one line element "
                                    "(a rod between its end nodes: elements: 1)");
      return elements[0];
    }
  return -1;
}

/// Change of the distance between line element `line`'s end nodes under field u (m).
double endElongation(const LineElement& line, const NodalField& u) {
  const auto [a, b] = line.endNodes();
  const Eigen::Vector3d d = (u.row(b).head<3>() - u.row(a).head<3>()).transpose();
  return d.dot(line.localAxes().row(0).transpose());
}

}  // namespace

OneWaySolution solveWithOneWayMembers(const OneWayModelBuilder& build,
                                      const std::vector<OneWayMember>& members,
                                      const StaticOptions& options) {
  const int n = int(members.size());
  const std::shared_ptr<const Model> allIn = build(std::vector<bool>(n, false));
  const Model& full = *allIn;
  std::vector<const LineElement*> lines(n);
  for (int i = 0; i < n; ++i) {
    const int e = oneWayElementOf(full, members[i].name);
    if (e < 0) throw std::invalid_argument("no member '" + members[i].name + "' in the model");
    lines[i] = asLine(full.elements()[e]);
    if (!lines[i]->spanLoad().isZero())
      throw std::invalid_argument("member '" + members[i].name +
                                  "' acts one way only and carries a span load (distributed or "
                                  "temperature): load its end nodes instead");
  }
  // > 0: by how much a force (or an elongation) has the sign member i cannot take.
  auto wrongWay = [&](int i, double value) {
    return members[i].acts == MemberAction::tensionOnly       ? -value
           : members[i].acts == MemberAction::compressionOnly ? value
                                                              : -1.0;
  };

  std::vector<bool> slack(n, false);
  std::set<std::vector<bool>> visited;
  bool oneAtATime = false;  // after a cycle, change only the worst violation per iteration
  const int maxIterations = 20 + 4 * n;
  OneWaySolution out;
  for (out.iterations = 1; out.iterations <= maxIterations; ++out.iterations) {
    // 1. Solve with the slack members out of action (contacts settle inside the solve).
    const std::shared_ptr<const Model> model =
        slack == std::vector<bool>(n, false) ? allIn : build(slack);
    const Model& solved = *model;
    StaticResult r = solveStatic(solved, options);

    std::vector<OneWayMemberState> states(n);
    // 2. Measure: in-action members whose force has the wrong sign, slack members whose ends
    //    move the way the member would resist. Scales: the largest displacement, and the largest reaction or member force.
    const double lengthScale = std::max(r.displacement.leftCols(3).cwiseAbs().maxCoeff(), 1e-300);
    double forceScale = 1e-300;
    for (const ReactionComponent& c : r.reactions)
      forceScale = std::max(forceScale, std::abs(c.value));
    for (int i = 0; i < n; ++i) {
      states[i] = {members[i].name, bool(slack[i]), 0.0,
                   endElongation(*lines[i], r.displacement)};
      if (!slack[i]) {  // (a slack member's resultants are zero)
        const int e = oneWayElementOf(solved, members[i].name);
        states[i].force = LoadedSolution(solved, r.displacement).forceSeries(e).at(0.5).N;
        forceScale = std::max(forceScale, std::abs(states[i].force));
      }
    }
    std::vector<bool> next = slack;
    int worst = -1;
    double worstAmount = 0;
    for (int i = 0; i < n; ++i) {
      const double amount = slack[i] ? wrongWay(i, -states[i].elongation) / lengthScale
                                     : wrongWay(i, states[i].force) / forceScale;
      if (amount > kOneWaySwitchTolerance) {
        next[i] = !slack[i];
        if (amount > worstAmount) worst = i, worstAmount = amount;
      }
    }
    // 3. Settled: report. Otherwise move on, one change at a time once a set repeats.
    if (worst < 0) {
      out.model = model;
      out.result = std::move(r);
      out.result.oneWayMembers = std::move(states);
      return out;
    }
    visited.insert(slack);
    if (oneAtATime || visited.count(next)) {
      oneAtATime = true;
      next = slack;
      next[worst] = !slack[worst];
    }
    slack = next;
  }
  std::ostringstream msg;
  msg << "static analysis: the tension-only / compression-only members did not settle after "
      << maxIterations << " iterations; members still switching:";
  for (int i = 0; i < n; ++i) msg << (i ? ", " : " ") << "'" << members[i].name << "'";
  throw SolveError(msg.str());
}

}  // namespace beamrotor
