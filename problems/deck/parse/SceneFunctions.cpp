#include "problems/deck/parse/SceneFunctions.hpp"

#include <muParser.h>

#include <cmath>
#include <exception>
#include <optional>
#include <string>

#include "problems/scenes/Mo10.hpp"

namespace beamrotor {

namespace {

/// The budget of this thread: how deep budgets are nested (0: none) and the cycles counted.
thread_local int budgetDepth = 0;
thread_local long long cyclesCounted = 0;

/// Counts `cycles` against the budget, or fails naming the limit when they do not fit.
void chargeCycles(long long cycles) {
  if (budgetDepth == 0) return;
  if (cycles > kMostClosedFormCycles - cyclesCounted)
    throw mu::Parser::exception_type(
        "the closed-form functions may compute at most " +
        std::to_string(kMostClosedFormCycles) +
        " MO-10 cycles in all while a deck is read (each expression is evaluated in several "
        "systems of units, and each evaluation counts); this call of " +
        std::to_string(cycles) + " cycles would take them past it, " +
        std::to_string(cyclesCounted) + " being computed already");
  cyclesCounted += cycles;
}

Mo10Parameters mo10(double J, double c, double l, double a, double H, double omega) {
  Mo10Parameters p;
  p.J = J;
  p.c = c;
  p.l = l;
  p.a = a;
  p.H = H;
  p.omega = omega;
  return p;
}

/// Checks a call's count of cycles and charges it to the budget.
void admitCycles(double cycles) {
  if (!(cycles >= 1 && cycles <= double(kMostCyclesPerCall)))
    throw mu::Parser::exception_type("MO-10 closed form: the number of cycles must lie in [1, " +
                                     std::to_string(kMostCyclesPerCall) + "]");
  chargeCycles((long long)std::ceil(cycles));
}

/// The closed form over `cycles` cycles; muparser reports the failure as its own error.
Mo10ClosedForm closedForm(const Mo10Parameters& p, double cycles,
                          Mo10ClosedForm::Start start = Mo10ClosedForm::Start::rest) {
  admitCycles(cycles);
  try {
    return Mo10ClosedForm(p, int(std::ceil(cycles)), start);
  } catch (const std::exception& e) {
    throw mu::Parser::exception_type(e.what());
  }
}

bool sameParameters(const Mo10Parameters& a, const Mo10Parameters& b) {
  return a.J == b.J && a.c == b.c && a.l == b.l && a.a == b.a && a.H == b.H &&
         a.omega == b.omega && a.muRatio == b.muRatio;
}

/// The form from rest over at least `cycles` cycles of this thread's last parameters, kept
/// between calls: a transient's history calls mo10_phi at every step with one set of
/// parameters, and building the cycles up to t at each call cost 60 % of the MO-10 deck's run.
/// The cycles are charged to the budget as if computed afresh, so a deck's reading is bounded
/// as before.
const Mo10ClosedForm& restForm(const Mo10Parameters& p, double cycles) {
  thread_local std::optional<Mo10ClosedForm> kept;
  if (!kept || !sameParameters(kept->parameters(), p)) {
    kept.reset();
    kept.emplace(closedForm(p, cycles));
  } else {
    admitCycles(cycles);
    kept->extend(int(std::ceil(cycles)));
  }
  return *kept;
}

double mo10Phi(double t, double J, double c, double l, double a, double H, double omega) {
  const Mo10Parameters p = mo10(J, c, l, a, H, omega);
  if (!(t >= 0)) throw mu::Parser::exception_type("mo10_phi: t must not be negative");
  // The cycles up to t (t = k T exactly is the end of cycle k, not the start of k + 1).
  const double cycles = std::max(1.0, std::ceil(t / p.period() * (1 - 1e-14)));
  return restForm(p, cycles).phiOverCycles(int(cycles), t);
}

double mo10PhiMax(double cycles, double J, double c, double l, double a, double H, double omega) {
  return closedForm(mo10(J, c, l, a, H, omega), cycles).extremes().amplitude;
}

double mo10ForceMax(double cycles, double J, double c, double l, double a, double H, double omega) {
  return closedForm(mo10(J, c, l, a, H, omega), cycles).extremes().pressingForce;
}

/// The periodic steady state, which repeats every cycle: phi at t (any t >= 0, read within
/// its cycle) and its extremes over one cycle.
Mo10ClosedForm steadyState(double J, double c, double l, double a, double H, double omega) {
  return closedForm(mo10(J, c, l, a, H, omega), 1, Mo10ClosedForm::Start::periodic);
}

double mo10SteadyPhi(double t, double J, double c, double l, double a, double H, double omega) {
  if (!(t >= 0)) throw mu::Parser::exception_type("mo10_steady_phi: t must not be negative");
  const Mo10ClosedForm form = steadyState(J, c, l, a, H, omega);
  const double T = form.parameters().period();
  return form.phi(t - T * std::floor(t / T));
}

double mo10SteadyPhiMax(double J, double c, double l, double a, double H, double omega) {
  return steadyState(J, c, l, a, H, omega).extremes().amplitude;
}

double mo10SteadyForceMax(double J, double c, double l, double a, double H, double omega) {
  return steadyState(J, c, l, a, H, omega).extremes().pressingForce;
}

}  // namespace

ClosedFormBudget::ClosedFormBudget() {
  if (budgetDepth++ == 0) cyclesCounted = 0;
}

ClosedFormBudget::~ClosedFormBudget() {
  --budgetDepth;
}

void defineSceneFunctions(mu::Parser& parser) {
  parser.DefineFun("mo10_phi", mo10Phi);
  parser.DefineFun("mo10_phi_max", mo10PhiMax);
  parser.DefineFun("mo10_force_max", mo10ForceMax);
  parser.DefineFun("mo10_steady_phi", mo10SteadyPhi);
  parser.DefineFun("mo10_steady_phi_max", mo10SteadyPhiMax);
  parser.DefineFun("mo10_steady_force_max", mo10SteadyForceMax);
}

}  // namespace beamrotor
