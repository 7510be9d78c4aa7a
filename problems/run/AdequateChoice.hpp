// What the cheapest-adequate-model search chose for a deck with `accuracy:` (RunResult's
// `adequate`), and what it cost against the deck's own mesh.
#pragma once

#include <optional>
#include <string>

namespace beamrotor {

struct AdequateChoice {
  double target = 0;            ///< the deck's `accuracy:` (relative)
  std::string formulation;      ///< the beam theory chosen, deck syntax ("euler-bernoulli")
  std::string deckFormulation;  ///< the deck's own (of its first segment)
  int elementsPerSegment = 0;   ///< the mesh chosen: 2^level elements on every segment
  int elements = 0, dofs = 0;   ///< of the chosen model (dofs: all, free and constrained)
  /// Estimated relative error on the checked quantities (largest over them): the change
  /// from the next coarser mesh (an upper estimate when the error falls monotonically at
  /// order >= 1) plus, when Euler-Bernoulli replaced the deck's Timoshenko beams, their
  /// difference (the shear contribution).
  double estimatedError = 0;
  double meshError = 0;                     ///< the mesh part
  std::optional<double> shearContribution;  ///< measured when the deck has Timoshenko beams
  double seconds = 0;                       ///< one solve of the chosen model
  double searchSeconds = 0;                 ///< every solve of the search, the chosen one included
  int deckElements = 0, deckDofs = 0;  ///< the deck's own mesh and formulation (the fixed mesh)
  double deckSeconds = 0;              ///< one solve of it
  /// Decks with a rigid-body and a modal analysis (a body on two springs, problems/scenes/README.md
  /// section 2): the largest relative difference of the two-dof closed-form frequencies from the
  /// two lowest FE frequencies of the chosen mesh, and whether it (plus the mesh error) is within
  /// the target, so that the rigid body alone is an adequate model.
  std::optional<double> rigidBodyError;
  bool rigidBodyAdequate = false;
};

}  // namespace beamrotor
