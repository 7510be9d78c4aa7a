// Mode shapes scaled for display: ARPACK returns mass-normalised vectors whose size and sign
// mean nothing to a reader, so the writers show every mode with its largest translation 1.
#pragma once

#include "fem/model/Model.hpp"
#include "fem/model/Results.hpp"

namespace beamrotor {

/// The shape scaled so that the largest nodal translation |(ux, uy, uz)| is 1 and the largest
/// translation component is positive (a deterministic sign). A mode with no translation worth
/// the name (pure torsion: translations below 1e-9 of the largest rotation times the model's
/// size) is scaled by its largest rotation instead. Rotations scale with the translations (rad
/// per unit of largest translation). A zero shape is returned unchanged.
NodalField displayModeShape(const Model& model, const NodalField& shape);

/// Whether a shape has no translation worth the name (pure torsion: translations below 1e-9
/// of the largest rotation times the model's size); displayModeShape scales such a shape by
/// its rotation.
bool isTorsionalShape(const Model& model, const NodalField& shape);

/// The translation kind (ux, uy or uz) with the largest value in a shape.
Dof dominantTranslation(const NodalField& shape);

/// The dof kind a chart draws a mode by: its dominant translation, or for a torsional shape
/// its dominant rotation (a torsion mode drawn by uy would be a flat line).
Dof chartedDof(const Model& model, const NodalField& shape);

}  // namespace beamrotor
