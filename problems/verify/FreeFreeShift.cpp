#include "problems/verify/FreeFreeShift.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "fem/modal/Modal.hpp"
#include "fem/solvers/Errors.hpp"
#include "problems/verify/VerifyModels.hpp"

namespace beamrotor::verify {

ShiftStudy freeFreeShiftStudy(const std::vector<double>& shiftRatios) {
  constexpr double kLength = 1.5;
  Model model;
  LineSpec spec;
  spec.dofs = DofSet{Dof::uy, Dof::rz};
  const auto section = steelRectangle(0.04, 0.04);
  spec.segments.push_back({kLength, section, 40, 0, {}});
  spec.points = {{"start", 0}, {"end", kLength}};
  buildLine(model, spec);
  // Free-free Euler-Bernoulli beam: omega_1 = (beta_1 L)^2 / L^2 sqrt(E I / (rho A)) with
  // beta_1 L = 4.730041 (Blevins, Formulas for Natural Frequency and Mode Shape, table 8-1).
  const double omega1 =
      std::pow(4.730041 / kLength, 2) * std::sqrt(section->EIz() / section->rhoA());
  const double lambda1 = omega1 * omega1, f1 = omega1 / (2 * std::numbers::pi);

  ShiftStudy study;
  try {
    solveModes(model, {3, 0});
  } catch (const SolveError& e) {
    study.zeroShiftError = e.what();
  }
  for (double ratio : shiftRatios) {
    const ModalResult r = solveModes(model, {3, -ratio * lambda1});
    ShiftPoint p;
    p.shiftRatio = ratio;
    p.elasticError = std::abs(r.modes.at(2).frequencyHz - f1) / f1;
    p.rigidBody =
        std::max(std::abs(r.modes[0].eigenvalue), std::abs(r.modes[1].eigenvalue)) / lambda1;
    study.points.push_back(p);
  }
  return study;
}

}  // namespace beamrotor::verify
