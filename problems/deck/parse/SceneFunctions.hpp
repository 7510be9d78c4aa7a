// Closed forms of the reference scenes as functions a deck's expressions can call, so a check
// can compare with a solution no short expression can write (one that runs over many cycles):
//   mo10_phi(t, J, c, l, a, H, omega)          MO-10 rotation phi(t) from rest (rad)
//   mo10_phi_max(cycles, J, c, l, a, H, omega) largest |phi| over the first `cycles` cycles
//   mo10_force_max(cycles, J, c, l, a, H, omega) largest |c (l phi + a)| over them (N)
//   mo10_steady_phi(t, J, c, l, a, H, omega)   phi(t) in the periodic steady state (rad)
//   mo10_steady_phi_max(J, c, l, a, H, omega)  its largest |phi| (rad)
//   mo10_steady_force_max(J, c, l, a, H, omega) its largest |c (l phi + a)| (N)
// (problems/scenes/README.md section 4, problems/scenes/Mo10; mu = 5 omega).
#pragma once

namespace mu {
class Parser;
}

namespace beamrotor {

/// Defines the functions above in `parser`.
void defineSceneFunctions(mu::Parser& parser);

}  // namespace beamrotor
