// Vibration about a loaded state: the modes of (K + KG(N)) x = omega^2 M x, KG the geometric
// stiffness of the axial forces the model's loads cause (first-order statics). A compressed
// member's frequencies drop, a tensioned one's rise; at the critical load the lowest one
// reaches zero.
#pragma once

#include "fem/modal/Modal.hpp"
#include "fem/model/Model.hpp"

namespace beamrotor {

/// The modes about the loaded state. Throws SolveError naming the buckling factor when the
/// load is at or past the critical one.
ModalResult solvePrestressedModes(const Model& model, const ModalOptions& options = {});

}  // namespace beamrotor
