// Bearing coefficients tabulated by spin speed and by whirl frequency (a user's table: a
// tilting-pad bearing's, a seal's or a damper's coefficients as a code or a test rig gives
// them): one row of eight coefficients per (speed, whirl frequency), every speed on the same
// whirl frequencies.
//
// Between rows: bilinear, linear in the speed and linear in the whirl frequency; the edge rows
// are held beyond the table in either direction (bearing data are not extrapolated). A motion
// e^{lambda t} reads the table at the whirl frequency omega = Im lambda (a table gives real
// frequencies only; exact for an undamped mode, and the usual reading of frequency-dependent
// coefficients for a damped one, Lund, ASME J. Tribology 109, 1987). The synchronous set is
// the table at whirl = spin.
#pragma once

#include <vector>

#include "elements/Bearing.hpp"

namespace beamrotor {

class WhirlTable : public WhirlCoefficients {
 public:
  /// rows[s * whirls.size() + w]: the coefficients (global axes) at speeds[s] (rad/s) and
  /// whirls[w] (rad/s), both strictly ascending and finite. Throws std::invalid_argument.
  WhirlTable(std::vector<double> speeds, std::vector<double> whirls,
             std::vector<BearingCoefficients> rows);

  BearingCoefficients at(double speed, std::complex<double> lambda) const override;
  const char* source() const override { return "table by whirl frequency"; }
  /// The coefficients at spin speed Omega and whirl frequency omega (rad/s).
  BearingCoefficients atWhirl(double speed, double whirl) const;
  /// The synchronous set at each table speed (whirl = spin), what the speed table holds.
  std::vector<BearingCoefficients> synchronous() const;
  const std::vector<double>& speeds() const { return speeds_; }

 private:
  /// The coefficients at table speed s and whirl frequency omega.
  BearingCoefficients atRow(std::size_t s, double whirl) const;

  std::vector<double> speeds_, whirls_;
  std::vector<BearingCoefficients> rows_;
};

}  // namespace beamrotor
