// Closed forms of the reference scenes as functions a deck's expressions can call, so a check
// can compare with a solution no short expression can write (one that runs over many cycles):
//   mo10_phi(t, J, c, l, a, H, omega)          MO-10 rotation phi(t) from rest (rad)
//   mo10_phi_max(cycles, J, c, l, a, H, omega) largest |phi| over the first `cycles` cycles
//   mo10_force_max(cycles, J, c, l, a, H, omega) largest |c (l phi + a)| over them (N)
//   mo10_steady_phi(t, J, c, l, a, H, omega)   phi(t) in the periodic steady state (rad)
//   mo10_steady_phi_max(J, c, l, a, H, omega)  its largest |phi| (rad)
//   mo10_steady_force_max(J, c, l, a, H, omega) its largest |c (l phi + a)| (N)
// (problems/scenes/README.md section 4, problems/scenes/Mo10; mu = 5 omega).
// Their cost grows with the cycles they compute, so it is bounded: one call at most
// kMostCyclesPerCall cycles, and while a deck is read all calls together at most
// kMostClosedFormCycles (ClosedFormBudget); past that a call fails, naming the limit. At run
// time (a transient's history values, once per step) each call is bounded alone: the steps
// are bounded, and a run's cost grows with them as the solve's own does.
#pragma once

namespace mu {
class Parser;
}

namespace beamrotor {

/// Defines the functions above in `parser`.
void defineSceneFunctions(mu::Parser& parser);

/// The most cycles one call may compute.
inline constexpr long long kMostCyclesPerCall = 100000;

/// The most cycles all calls may compute together under one ClosedFormBudget: about a second
/// of work on one core (an expression read from a deck is evaluated in several systems of
/// units to find its dimension, and every evaluation counts), far beyond what the shipped
/// decks need (about a hundred per reading).
inline constexpr long long kMostClosedFormCycles = 250000;

/// While one exists on a thread, the closed-form functions called on that thread count the
/// cycles they compute, and a call that would take the count past kMostClosedFormCycles fails
/// instead. A budget made while another exists shares it.
class ClosedFormBudget {
 public:
  ClosedFormBudget();
  ~ClosedFormBudget();
  ClosedFormBudget(const ClosedFormBudget&) = delete;
  ClosedFormBudget& operator=(const ClosedFormBudget&) = delete;
};

}  // namespace beamrotor
