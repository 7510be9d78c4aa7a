// A gear mesh joining the twist of two shafts: the wheel on node b turns `ratio` times slower
// than the pinion on node a (a speed reduction ratio = w_a / w_b), so their rigid motion is
// theta_a = ratio theta_b (each shaft's twist counted positive in its own sense of rotation).
// The mesh's flexibility is a torsional spring on the pinion's side: its deflection, referred
// to shaft a, is d = theta_a - ratio theta_b, and it stores k d^2 / 2. Hence
//   K = k [1, -ratio; -ratio, ratio^2],  C likewise with the mesh damping c,
// and a shaft beyond the mesh enters the equations of shaft a with its inertias and stiffnesses
// divided by ratio^2 (the classical reduction of a geared train, e.g. Den Hartog, Mechanical
// Vibrations, 4th ed., sec. 5.2; Rao, Mechanical Vibrations, sec. 6.13).
#pragma once

#include <array>
#include <cstdint>

#include "fem/model/Element.hpp"

namespace beamrotor {

class GearMesh : public Element {
 public:
  /// a, b: the pinion's and the wheel's nodes (their rx); ratio = w_a / w_b > 0; k (N m/rad)
  /// and c (N m s/rad) on shaft a's side. Throws std::invalid_argument on a bad value.
  GearMesh(int a, int b, double ratio, double stiffness, double damping = 0);
  ElementDofs dofs() const override { return {nodes_, codes_.data(), 2}; }
  ElementMatrix stiffness() const override { return pattern(k_); }
  ElementMatrix damping() const override { return c_ != 0 ? pattern(c_) : ElementMatrix{}; }
  std::string kind() const override { return "gear-mesh"; }
  double ratio() const { return ratio_; }
  double stiffnessValue() const { return k_; }
  double dampingValue() const { return c_; }

 private:
  ElementMatrix pattern(double value) const;
  std::array<int, 2> nodes_{};
  std::array<std::uint8_t, 2> codes_{};
  double ratio_, k_, c_;
};

}  // namespace beamrotor
