// Solving a torsion analysis (problems/deck/torsion/TorsionKind.hpp). Without a `train:` it
// twists the deck's shaft line with the twist rx as its only dof, the masses' Jp and the
// supports and springs that act on rx; bearings, loads and the other dofs play no part in
// free torsional vibration of a straight shaft along x, which decouples from bending and
// axial motion. With a train it builds the train (meshes/TrainBuilder.hpp), finds its modes,
// where the analysis' orders cross them over its speed range, and its steady response to the
// harmonic torques (fem/modal/HarmonicResponse.hpp) at the operating speed and over the range.
#pragma once

#include "problems/deck/Deck.hpp"
#include "problems/run/TorsionOutcome.hpp"

namespace beamrotor {

/// Throws what the core throws (SolveError); the caller reports it at the analysis.
TorsionOutcome runTorsion(const Deck& deck, const TorsionSpec& spec);

}  // namespace beamrotor
