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
//
// Two close peaks: the half-power method needs the response to fall to peak / sqrt(2) on both
// sides of a peak; when a neighbouring peak's skirt holds it up (the response rises again
// before falling that far), the half-power points do not exist and no bandwidth can be read.
// Such a peak is marked `overlapping`, and its amplification factor can be taken from the
// damping of the mode itself: for a lightly damped mode the half-power bandwidth is 2 zeta Nc,
// so AF = 1 / (2 zeta), zeta the damping ratio of the damped eigenvalue at that critical speed
// (API RP 684 allows the factor from the modal damping; Friswell et al. 2010, sec. 1.6).
#pragma once

#include <string_view>
#include <vector>

namespace beamrotor {

/// How a peak's amplification factor was found.
enum class AmplificationMethod {
  none,          ///< not found: no half-power points and no modal damping given
  halfPower,     ///< Nc / (N2 - N1) from the response's half-power points
  modalDamping,  ///< 1 / (2 zeta) of the damped mode at the peak (overlapping peaks)
};
/// "none", "half-power", "modal-damping".
std::string_view amplificationMethodName(AmplificationMethod m);

struct ResponsePeak {
  double speed = 0;      ///< rad/s, the peak of the parabola through the largest sample and its
                         ///< neighbours
  double amplitude = 0;  ///< m, that parabola's top
  /// Half-power speeds (rad/s), linearly interpolated between samples; 0 where the response
  /// does not fall to peak / sqrt(2) within the sweep on that side.
  double lowerHalfPower = 0, upperHalfPower = 0;
  bool halfPowerFound = false;        ///< both half-power points lie in the sweep
  /// on a side, the response rises again (a neighbouring peak) before falling to
  /// peak / sqrt(2): the half-power method cannot read this peak
  bool overlapping = false;
  AmplificationMethod method = AmplificationMethod::none;
  double dampingRatio = 0;            ///< modalDamping: the mode's zeta; else 0
  double amplificationFactor = 0;     ///< by `method`; 0 when not found
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

/// Gives an overlapping peak (or any without half-power points) the amplification factor
/// 1 / (2 zeta) of its mode, zeta > 0 the damping ratio of the damped eigenvalue at the peak,
/// and judges its margin with it. Throws std::invalid_argument for zeta <= 0 (an undamped or
/// unstable mode has no finite factor).
void useModalDamping(ResponsePeak& peak, double dampingRatio, const OperatingRange& operating);

/// The margin API 617 requires for amplification factor AF of a critical below (or, with
/// `above`, above) the operating range (%).
double requiredSeparationMargin(double amplificationFactor, bool above);

}  // namespace beamrotor
