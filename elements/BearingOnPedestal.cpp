#include "elements/BearingOnPedestal.hpp"

namespace beamrotor {

namespace {

/// [B -B; -B B] of a 2 x 2 block; empty for an empty one.
ElementMatrix relative(const ElementMatrix& B) {
  if (B.size() == 0) return {};
  ElementMatrix out(4, 4);
  out << B, -B, -B, B;
  return out;
}

}  // namespace

BearingOnPedestal::BearingOnPedestal(int journal, int housing, std::vector<double> speeds,
                                     std::vector<BearingCoefficients> table)
    : film_(journal, std::move(speeds), std::move(table)), journal_(journal), housing_(housing) {}

ElementDofs BearingOnPedestal::dofs() const {
  static constexpr std::uint8_t codes[] = {elementDofCode(0, Dof::uy), elementDofCode(0, Dof::uz),
                                           elementDofCode(1, Dof::uy), elementDofCode(1, Dof::uz)};
  return {{journal_, housing_}, codes, 4};
}

ElementMatrix BearingOnPedestal::stiffnessAt(double speed) const {
  return relative(film_.stiffnessAt(speed));
}

ElementMatrix BearingOnPedestal::dampingAt(double speed) const {
  return relative(film_.dampingAt(speed));
}

EigenvalueMatrices BearingOnPedestal::atEigenvalue(double speed,
                                                  std::complex<double> lambda) const {
  const EigenvalueMatrices film = film_.atEigenvalue(speed, lambda);
  return {relative(film.stiffness), relative(film.damping)};
}

}  // namespace beamrotor
