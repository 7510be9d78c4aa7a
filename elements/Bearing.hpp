// A bearing: one shaft node tied to the fixed frame in the two lateral directions by
// stiffness and damping coefficients, constant or tabulated against spin speed.
//
// Frame: a shaft along global x; the bearing's own transverse axes (x_b, y_b), in which
// bearing data are usually printed as kxx, kxy, kyx, kyy, map to global (y, z):
// kxx -> kyy, kxy -> kyz, kyx -> kzy, kyy -> kzz (likewise for c). The force the bearing
// exerts on the journal is
//   F = -[kyy kyz; kzy kzz] (uy, uz) - [cyy cyz; czy czz] (uy', uz')   (N; m, m/s).
// Cross-coupled coefficients make K and C non-symmetric.
#pragma once

#include <array>
#include <complex>
#include <memory>
#include <vector>

#include "fem/model/RotorElement.hpp"

namespace beamrotor {

/// Bearing coefficients at one speed, global axes: N/m and N s/m.
struct BearingCoefficients {
  double kyy = 0, kyz = 0, kzy = 0, kzz = 0;
  double cyy = 0, cyz = 0, czy = 0, czz = 0;

  /// Isotropic bearing: k on both directions, no cross-coupling.
  static BearingCoefficients isotropic(double k, double c = 0) { return {k, 0, 0, k, c, 0, 0, c}; }
};

/// Where `speed` falls in a strictly ascending list: the row below (`low`) and the fraction t
/// of the step to the next; t = 0 at or below the first row, the last row (t = 0) at or above
/// the last (tables are held beyond their ends, not extrapolated).
struct TableBracket {
  std::size_t low = 0;
  double t = 0;
};
TableBracket tableBracket(const std::vector<double>& rows, double value);

/// (1 - t) a + t b, coefficient by coefficient.
BearingCoefficients blend(const BearingCoefficients& a, const BearingCoefficients& b, double t);

/// Coefficients that depend on the frequency of the journal's motion as well as on the spin
/// speed (a tilting-pad bearing, a table by whirl frequency).
class WhirlCoefficients {
 public:
  virtual ~WhirlCoefficients() = default;
  /// K and C (N/m, N s/m; global axes) at spin speed Omega (rad/s) seen by a motion
  /// e^{lambda t} (1/s, Im lambda >= 0): K + lambda C is the bearing's impedance there.
  virtual BearingCoefficients at(double speed, std::complex<double> lambda) const = 0;
  /// A name for the outputs: what the coefficients were taken from.
  virtual const char* source() const = 0;
};

class Bearing : public SpeedDependentElement {
 public:
  /// Constant coefficients at `node` (dofs uy, uz).
  Bearing(int node, const BearingCoefficients& c);
  /// Coefficients tabulated at strictly ascending speeds (rad/s); linear interpolation
  /// between rows, the end rows held beyond the table (bearing data are not extrapolated).
  Bearing(int node, std::vector<double> speeds, std::vector<BearingCoefficients> table);

  ElementDofs dofs() const override { return lateralDofs(node_); }
  ElementMatrix stiffnessAt(double speed) const override;
  ElementMatrix dampingAt(double speed) const override;
  std::string kind() const override { return "bearing"; }

  /// The interpolated coefficients at spin speed Omega (rad/s).
  BearingCoefficients coefficientsAt(double speed) const;

  /// Coefficients by whirl as well (the speed table then holds their synchronous set, which
  /// the analyses at one frequency, the spin's, read); null: none.
  void setWhirlCoefficients(std::shared_ptr<const WhirlCoefficients> whirl);
  const std::shared_ptr<const WhirlCoefficients>& whirlCoefficients() const { return whirl_; }
  bool dependsOnWhirl() const override { return whirl_ != nullptr; }
  EigenvalueMatrices atEigenvalue(double speed, std::complex<double> lambda) const override;

 private:
  int node_;
  std::vector<double> speeds_;
  std::vector<BearingCoefficients> table_;
  std::shared_ptr<const WhirlCoefficients> whirl_;
};

}  // namespace beamrotor
