// The discretisations a convergence study compares, and the refinements it applies: level k
// multiplies every segment's element count by 2^k (halves every element size), or for a
// transient quantity divides the time step by 2^k.
#pragma once

#include <string>
#include <vector>

#include "elements/Beam.hpp"
#include "problems/deck/Deck.hpp"

namespace beamrotor {

/// One element formulation with its mass model.
struct ConvergeMethod {
  std::string name;   ///< stable key in convergence.json, e.g. "eb-consistent"
  std::string label;  ///< for chart keys, e.g. "Euler-Bernoulli, consistent mass"
  BeamTheory theory = BeamTheory::eulerBernoulli;
  MassModel mass = MassModel::consistent;
};

/// The methods worth comparing for a quantity: Euler-Bernoulli (consistent and, when the mass
/// matters, lumped mass), the locking-free Timoshenko element, and the linear Timoshenko
/// element with full (locking) and reduced (1-point shear) integration.
std::vector<ConvergeMethod> convergeMethods(bool massMatters);

/// Gives the deck's model and every segment the method's theory and mass model (rotary
/// inertia and end releases are kept).
void useMethod(const ConvergeMethod& method, Deck& deck);

/// Level k of the refinement: element counts times 2^k, element sizes divided by 2^k.
void refineMesh(Deck& deck, int level);

/// Level k of a time-step study: every transient analysis' dt divided by 2^k.
void refineTimeStep(Deck& deck, int level);

}  // namespace beamrotor
