// The acceleration response spectrum a response-spectrum analysis reads: the peak
// pseudo-acceleration Sa (m/s^2) of a damped single oscillator against its natural period,
// given as a table or as the elastic spectrum of EN 1998-1:2004, 3.2.2.2.
#pragma once

#include <string>
#include <vector>

namespace beamrotor {

/// The ground types of EN 1998-1 Tables 3.2 and 3.3.
enum class GroundType { A, B, C, D, E };

/// The four figures that shape an EN 1998-1 elastic spectrum: the soil factor S and the corner
/// periods TB, TC, TD (s).
struct SpectrumCorners {
  double S = 1, TB = 0, TC = 0, TD = 0;
};

/// EN 1998-1:2004 Table 3.2 (type 1, high seismicity) or Table 3.3 (type 2, magnitude up to
/// 5.5), the recommended values; `type` is 1 or 2.
SpectrumCorners en1998Corners(int type, GroundType ground);

/// EN 1998-1:2004 (3.6): the damping correction eta = sqrt(10 / (5 + xi)), xi in percent,
/// and at least 0.55; 1 at 5 %.
double en1998DampingCorrection(double dampingRatio);

class DesignSpectrum {
 public:
  /// The EN 1998-1 horizontal elastic spectrum (3.2)-(3.5) at design ground acceleration ag
  /// (m/s^2) on ground type A-E, for viscous damping ratio `dampingRatio` (0.05 for 5 %).
  static DesignSpectrum en1998(int type, GroundType ground, double ag, double dampingRatio);
  /// The EN 1998-1 vertical elastic spectrum (3.8)-(3.11) of Table 3.4: avg = 0.90 ag (type 1)
  /// or 0.45 ag (type 2), TB = 0.05, TC = 0.15, TD = 1.0 s, the plateau 3.0 eta avg, whatever
  /// the ground.
  static DesignSpectrum en1998Vertical(int type, double ag, double dampingRatio);
  /// Sa (m/s^2) at the periods (s, ascending, distinct), linear between them; outside the
  /// table its end values hold (the first for stiffer modes, the last for softer ones).
  static DesignSpectrum table(std::vector<double> periods, std::vector<double> accelerations);

  /// Sa (m/s^2) at period T (s).
  double at(double period) const;
  /// Whether a table gives Sa at T itself (a code shape covers every period).
  bool covers(double period) const;
  /// "EN 1998-1 type 1, ground B, ag = 2.5 m/s^2, 5 % damping (eta = 1)", "EN 1998-1 type 1
  /// vertical, avg = ..." or "table of N periods".
  std::string describe() const;
  bool isTable() const { return !periods_.empty(); }
  const SpectrumCorners& corners() const { return corners_; }
  /// The periods where the spectrum's slope changes (its corners or its table's periods), for
  /// charts.
  std::vector<double> breakPeriods() const;

 private:
  // EN 1998-1 shape
  int type_ = 1;
  GroundType ground_ = GroundType::A;
  bool vertical_ = false;
  SpectrumCorners corners_;
  double ag_ = 0, eta_ = 1, damping_ = 0.05;  ///< ag_: avg for the vertical spectrum
  double plateauFactor_ = 2.5;                 ///< 2.5 horizontal (3.3), 3.0 vertical (3.9)
  // table
  std::vector<double> periods_, accelerations_;
};

}  // namespace beamrotor
