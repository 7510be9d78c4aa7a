// The cheapest adequate model of a deck with `accuracy: TARGET`: the coarsest mesh, and
// Euler-Bernoulli beams instead of the deck's Timoshenko beams where the shear contribution
// is small enough, whose checked quantities are estimated to be within TARGET (relative).
//
// 1. Mesh: every segment gets 2^k elements, k = 0, 1, ...; the first k whose checked values
//    differ from level k-1 by at most the target (relatively, the largest over the checks)
//    is chosen, that change being its estimated error (a level whose mesh is no finer than
//    the one before, because points already split the segments, is not compared). For an error
//    falling monotonically as C h^p the change is (2^p - 1) times the error of level k, so it
//    over-estimates it for any order p >= 1 (the Euler-Bernoulli element converges at p = 2 to 4,
//    or is exact).
// 2. Theory: when the deck has Timoshenko beams, the same search with Euler-Bernoulli beams;
//    their difference from the Timoshenko result is the shear contribution. Euler-Bernoulli
//    is chosen when its mesh estimate plus the shear contribution is within the target.
// 3. The chosen model is solved once more, timed, and so is the deck's own mesh (the fixed
//    mesh it replaces), for the cost comparison.
// 4. A deck with a rigid-body analysis and a modal one (a body on two springs): the two-dof
//    closed form's frequencies against the two lowest FE ones; when they differ by less
//    than the target (less the mesh error), the rigid body is reported adequate: no beam
//    model is needed for those frequencies (the scene's "no more model than needed").
#pragma once

#include "problems/deck/Deck.hpp"
#include "problems/run/RunResult.hpp"

namespace beamrotor {

/// Levels tried: up to 2^kMaxAdequateLevel elements per segment.
inline constexpr int kMaxAdequateLevel = 12;

/// The run of the chosen model (its analyses and checks), with run.adequate filled. Throws
/// DeckSolveError at the `accuracy:` field when no level up to kMaxAdequateLevel reaches it.
RunResult runAdequateModel(const Deck& deck);

}  // namespace beamrotor
