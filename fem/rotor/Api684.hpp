// The API 684 / API 617 reading of an unbalance response: each resonance peak's speed and
// amplitude, its amplification factor by the half-power method, and the separation margin
// from the operating speed range that factor calls for against the one the rotor has.
//
// (American Petroleum Institute, API Standard Paragraphs Rotordynamic Tutorial, API RP 684,
// 2nd ed. 2005, sec. 2.8; API 617, 8th ed. 2014, 4.8.2.10; also Friswell et
// al., Dynamics of Rotating Machines, 2010, sec. 1.6.) The half-power points N1 < Nc < N2 are
// where the amplitude is the peak's divided by sqrt(2); AF = Nc / (N2 - N1), about 1 / (2 zeta)
// for a lightly damped mode. With AF < 2.5 the mode is critically damped and needs no margin.
// Otherwise a critical below the operating range must lie SM = 17 (1 - 1 / (AF - 1.5)) %
// below its lowest speed, one above it SM = 10 + 17 (1 - 1 / (AF - 1.5)) % above its highest.
#pragma once

#include <vector>

namespace beamrotor {

struct ResponsePeak {
  double speed = 0;      ///< rad/s, the peak of the parabola through the largest sample and its
                         ///< neighbours
  double amplitude = 0;  ///< m, that parabola's top
  /// Half-power speeds (rad/s), linearly interpolated between samples; 0 where the response
  /// does not fall to peak / sqrt(2) within the sweep on that side.
  double lowerHalfPower = 0, upperHalfPower = 0;
  bool halfPowerFound = false;        ///< both half-power points lie in the sweep
  double amplificationFactor = 0;     ///< Nc / (N2 - N1); 0 when not found
  double requiredMargin = 0;          ///< %, 0 when none is required (AF < 2.5)
  double actualMargin = 0;            ///< %, distance to the operating range (< 0 inside it)
  bool pass = false;                  ///< actual >= required (and AF known)
};

/// The operating speed range (rad/s) the margins are measured from.
struct OperatingRange {
  double minimum = 0, maximum = 0;
};

/// The peaks (interior local maxima) of `amplitudes` sampled at ascending `speeds`, each read
/// as above.
std::vector<ResponsePeak> readResponsePeaks(const std::vector<double>& speeds,
                                            const std::vector<double>& amplitudes,
                                            const OperatingRange& operating);

/// The margin API 617 requires for amplification factor AF of a critical below (or, with
/// `above`, above) the operating range (%).
double requiredSeparationMargin(double amplificationFactor, bool above);

}  // namespace beamrotor
