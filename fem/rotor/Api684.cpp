#include "fem/rotor/Api684.hpp"

#include <cmath>
#include <stdexcept>
#include <string_view>

namespace beamrotor {

namespace {

/// Where the samples a -> b (speeds sa, sb) cross `level`, linearly.
double crossing(double sa, double a, double sb, double b, double level) {
  return a == b ? sa : sa + (level - a) / (b - a) * (sb - sa);
}

/// The required margin for the peak's amplification factor and whether the actual one meets
/// it.
void judge(ResponsePeak& p, const OperatingRange& operating) {
  p.requiredMargin = requiredSeparationMargin(p.amplificationFactor, p.speed >= operating.minimum);
  p.pass = p.requiredMargin == 0 || p.actualMargin >= p.requiredMargin;
}

}  // namespace

std::string_view amplificationMethodName(AmplificationMethod m) {
  switch (m) {
    case AmplificationMethod::halfPower: return "half-power";
    case AmplificationMethod::modalDamping: return "modal-damping";
    case AmplificationMethod::none: break;
  }
  return "none";
}

void useModalDamping(ResponsePeak& p, double zeta, const OperatingRange& operating) {
  if (!(zeta > 0))
    throw std::invalid_argument("the amplification factor 1 / (2 zeta) needs a damping ratio > 0");
  p.method = AmplificationMethod::modalDamping;
  p.dampingRatio = zeta;
  p.amplificationFactor = 1 / (2 * zeta);
  judge(p, operating);
}

double requiredSeparationMargin(double af, bool above) {
  if (af < 2.5) return 0;
  const double margin = 17 * (1 - 1 / (af - 1.5));
  return above ? 10 + margin : margin;
}

std::vector<ResponsePeak> readResponsePeaks(const std::vector<double>& speeds,
                                            const std::vector<double>& amplitudes,
                                            const OperatingRange& operating) {
  if (speeds.size() != amplitudes.size())
    throw std::invalid_argument("one amplitude per speed expected");
  std::vector<ResponsePeak> out;
  const std::size_t n = speeds.size();
  for (std::size_t i = 1; i + 1 < n; ++i) {
    const double a = amplitudes[i];
    if (!(a > amplitudes[i - 1] && a >= amplitudes[i + 1])) continue;
    ResponsePeak p;
    // 1. The top of the parabola through the three samples (exact for a smooth peak sampled
    //    finely: the error falls as the cube of the step).
    const double x0 = speeds[i - 1], x1 = speeds[i], x2 = speeds[i + 1];
    const double y0 = amplitudes[i - 1], y2 = amplitudes[i + 1];
    const double d01 = (a - y0) / (x1 - x0), d12 = (y2 - a) / (x2 - x1);
    const double curvature = (d12 - d01) / (x2 - x0);
    p.speed = x1, p.amplitude = a;
    if (curvature < 0) {
      const double top = 0.5 * (x0 + x1) - d01 / (2 * curvature);
      if (top > x0 && top < x2) {
        p.speed = top;
        p.amplitude = a + d01 * (top - x1) + curvature * (top - x0) * (top - x1);
      }
    }
    // 2. The half-power points: the nearest samples on each side below peak / sqrt(2).
    const double level = p.amplitude / std::sqrt(2.0);
    std::size_t lo = i, hi = i;
    while (lo > 0 && amplitudes[lo - 1] >= level && amplitudes[lo - 1] <= amplitudes[lo]) --lo;
    while (hi + 1 < n && amplitudes[hi + 1] >= level && amplitudes[hi + 1] <= amplitudes[hi]) ++hi;
    const bool lowFound = lo > 0 && amplitudes[lo - 1] < level;
    const bool highFound = hi + 1 < n && amplitudes[hi + 1] < level;
    if (lowFound)
      p.lowerHalfPower = crossing(speeds[lo - 1], amplitudes[lo - 1], speeds[lo], amplitudes[lo], level);
    if (highFound)
      p.upperHalfPower =
          crossing(speeds[hi], amplitudes[hi], speeds[hi + 1], amplitudes[hi + 1], level);
    p.halfPowerFound = lowFound && highFound;
    // A side that stopped above the level before the sweep's end met a rising response.
    p.overlapping = (!lowFound && lo > 0) || (!highFound && hi + 1 < n);
    // 3. Margins against the operating range.
    const bool above = p.speed > operating.maximum;
    const bool below = p.speed < operating.minimum;
    p.actualMargin = below   ? 100 * (operating.minimum - p.speed) / operating.minimum
                     : above ? 100 * (p.speed - operating.maximum) / operating.maximum
                             : -100 * std::min(p.speed - operating.minimum,
                                               operating.maximum - p.speed) /
                                   operating.maximum;
    if (p.halfPowerFound) {
      p.method = AmplificationMethod::halfPower;
      p.amplificationFactor = p.speed / (p.upperHalfPower - p.lowerHalfPower);
      judge(p, operating);
    }
    out.push_back(p);
  }
  return out;
}

}  // namespace beamrotor
