// Functions decks may call in expressions beyond muparser's own (sin, sqrt, min, ...). Each
// wraps a scene model of problems/scenes, so a deck can derive its parameters from a machine's
// kinematics instead of restating the formulas:
//   crank_position(r, l, phi)   slider displacement (m) from the outer dead centre of a
//                               crank-slider with crank radius r and rod length l (m), crank
//                               angle phi (rad) from that dead centre: exact kinematics,
//                               x = r (1 - cos phi) + l (1 - cos beta), sin beta = (r/l) sin phi
//                               (problems/scenes/CrankSlider, crank::exactInPhi); 0 at phi = 0,
//                               2 r at phi = pi.
//   crank_rod_angle(r, l, phi)  the connecting rod's angle beta (rad) to the line of stroke.
// Arguments outside a function's domain (here: unless 0 < r < l) make the expression fail with
// a message naming the function.
#pragma once

namespace mu {
class Parser;
}

namespace beamrotor {

/// Defines the functions above on parser.
void defineDeckFunctions(mu::Parser& parser);

}  // namespace beamrotor
