// Contact constraints by an active-set iteration: solve with the active stops held at their
// bounds, close stops the solution passes, open stops that pull, repeat until nothing changes.
// Each iteration is one numeric factorisation on the pattern analysed once.
#pragma once

#include <vector>

#include "fem/static/LinearStatics.hpp"

namespace beamrotor {

struct ActiveSetSolution {
  Eigen::VectorXd displacement;        ///< full-length
  std::vector<ContactState> contacts;  ///< model order
  int iterations = 0;                  ///< linear solves
};

/// Solves system for model's contacts. Throws SolveError when the set does not settle.
ActiveSetSolution solveWithContacts(const Model& model, LinearStatics& system,
                                    double singularRcond);

}  // namespace beamrotor
