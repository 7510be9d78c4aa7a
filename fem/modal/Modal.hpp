// Free vibration: the lowest modes of K x = omega^2 M x with supports held fixed.
#pragma once

#include "fem/model/Model.hpp"
#include "fem/model/Results.hpp"

namespace beamrotor {

struct ModalOptions {
  int modes = 6;     ///< how many modes
  double shift = 0;  ///< sigma (rad^2/s^2): modes nearest it; negative for free-free models
};

/// Solves for the modes nearest the shift (ascending). Prescribed support values are ignored:
/// vibration is about the equilibrium. Throws SolveError for a singular K - sigma M.
ModalResult solveModes(const Model& model, const ModalOptions& options = {});

/// The same about a loaded state: the geometric stiffness of the full-length displacement
/// `state` (ordered as DofMap) is added to K (fem/stability/Prestressed).
ModalResult solveModesAbout(const Model& model, const ModalOptions& options,
                            const Eigen::VectorXd& state);

}  // namespace beamrotor
