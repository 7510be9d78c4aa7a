#include "fem/static/ActiveSet.hpp"

#include <cmath>
#include <set>
#include <sstream>

#include "fem/solvers/Errors.hpp"

namespace beamrotor {

namespace {

// A value within this fraction of the problem's displacement scale counts as on the bound,
// and a stop force within it of the force scale counts as zero: round-off of the solve
// (~1e-16 times the condition number), far below any physical gap or force. At an exact
// switch point the open and the closed solution coincide, so either choice is right.
constexpr double kRelativeTolerance = 1e-9;

enum class Side { open, lower, upper };

struct Iterate {
  std::vector<Side> side;
  bool operator<(const Iterate& o) const { return side < o.side; }
};

double scale(const Eigen::VectorXd& v) {
  return std::max(v.cwiseAbs().maxCoeff(), 1e-300);
}

}  // namespace

ActiveSetSolution solveWithContacts(const Model& model, LinearStatics& system,
                                    double singularRcond) {
  const auto& contacts = model.contacts();
  const int n = int(contacts.size());
  const DofMap& dofs = system.dofs();
  std::vector<int> eq(n);
  for (int i = 0; i < n; ++i) eq[i] = dofs.equation(contacts[i].node, contacts[i].dof);
  auto boundOf = [&](int i, Side s) {
    return s == Side::lower ? contacts[i].lower : contacts[i].upper;
  };

  Iterate state{std::vector<Side>(n, Side::open)};
  std::set<Iterate> visited;
  bool oneAtATime = false;  // after a cycle, change only the worst violation per iteration
  const int maxIterations = 20 + 4 * n;
  ActiveSetSolution out;
  for (out.iterations = 1; out.iterations <= maxIterations; ++out.iterations) {
    // 1. Solve with the active stops held.
    std::vector<HeldDof> held;
    for (int i = 0; i < n; ++i)
      if (state.side[i] != Side::open) held.push_back({eq[i], boundOf(i, state.side[i])});
    Eigen::VectorXd u;
    try {
      u = system.solve(held, singularRcond);
    } catch (const UnsupportedStructure&) {
      // A structure that stands only on its stops (a beam resting on unilateral supports)
      // is a mechanism while they are open: start again from all stops closed.
      if (out.iterations > 1 || n == 0) throw;
      for (int i = 0; i < n; ++i)
        state.side[i] = std::isfinite(contacts[i].lower) &&
                                (!std::isfinite(contacts[i].upper) ||
                                 std::abs(contacts[i].lower) <= std::abs(contacts[i].upper))
                            ? Side::lower
                            : Side::upper;
      continue;
    }
    const Eigen::VectorXd r = system.residual(u);
    const double uTol = kRelativeTolerance * scale(u), fTol = kRelativeTolerance * scale(r);

    // 2. Measure violations: open stops passed, active stops pulling.
    Iterate next = state;
    int worst = -1;
    double worstAmount = 0;
    auto propose = [&](int i, Side s, double amount) {
      next.side[i] = s;
      if (amount > worstAmount) worst = i, worstAmount = amount;
    };
    for (int i = 0; i < n; ++i) {
      const double v = u[eq[i]], f = r[eq[i]];
      switch (state.side[i]) {
        case Side::open:
          if (v < contacts[i].lower - uTol) propose(i, Side::lower, (contacts[i].lower - v) / uTol);
          if (v > contacts[i].upper + uTol) propose(i, Side::upper, (v - contacts[i].upper) / uTol);
          break;
        case Side::lower:  // the stop can only push the dof up
          if (f < -fTol) propose(i, Side::open, -f / fTol);
          break;
        case Side::upper:
          if (f > fTol) propose(i, Side::open, f / fTol);
          break;
      }
    }

    // 3. Settled: report. Otherwise move on, one change at a time once a set repeats.
    if (worst < 0) {
      out.displacement = u;
      for (int i = 0; i < n; ++i) {
        const ContactConstraint& c = contacts[i];
        ContactState s{c.name, c.node, c.dof};
        s.active = state.side[i] != Side::open;
        s.value = u[eq[i]];
        const double toLower = s.value - c.lower, toUpper = c.upper - s.value;
        s.bound = s.active ? boundOf(i, state.side[i]) : (toLower < toUpper ? c.lower : c.upper);
        s.gap = s.active ? 0.0 : std::min(toLower, toUpper);
        s.force = s.active ? r[eq[i]] : 0.0;
        out.contacts.push_back(s);
      }
      return out;
    }
    visited.insert(state);
    if (oneAtATime || visited.count(next)) {
      oneAtATime = true;
      Iterate single = state;
      single.side[worst] = next.side[worst];
      next = single;
    }
    state = next;
  }
  std::ostringstream msg;
  msg << "static analysis: the contact set did not settle after " << maxIterations
      << " iterations; contacts still switching:";
  for (int i = 0; i < n; ++i) msg << (i ? ", " : " ") << "'" << contacts[i].name << "'";
  throw SolveError(msg.str());
}

}  // namespace beamrotor
