// Solving a torsion analysis (problems/deck/torsion/TorsionKind.hpp): the deck's shaft line
// with the twist rx as its only dof, the masses' Jp and the supports and springs that act
// on rx; bearings, loads and the other dofs play no part in free torsional vibration of a
// straight shaft along x, which decouples from bending and axial motion.
#pragma once

#include "problems/deck/Deck.hpp"
#include "problems/run/TorsionOutcome.hpp"

namespace beamrotor {

/// Throws what the core throws (SolveError); the caller reports it at the analysis.
TorsionOutcome runTorsion(const Deck& deck, const TorsionSpec& spec);

}  // namespace beamrotor
