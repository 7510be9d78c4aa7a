#include "fem/rotor/SpeedRoot.hpp"

#include <cmath>

namespace beamrotor {

SpeedRoot speedRoot(const std::function<double(double)>& f, double a, double fa, double b,
                    double fb, double tolerance) {
  const double lower = a, upper = b;
  const bool upperSign = fb > 0;  // a speed whose value has this sign replaces b
  SpeedRoot root;
  double c = b;
  int kept = 0;  // -1: a kept last time, +1: b kept
  for (int i = 0; i < 200 && b - a > tolerance * b; ++i) {
    c = fa == fb ? 0.5 * (a + b) : b - fb * (b - a) / (fb - fa);
    if (!(c > a && c < b)) c = 0.5 * (a + b);
    const double fc = f(c);
    ++root.evaluations;
    if (fc == 0) break;
    if ((fc > 0) == upperSign) {
      b = c, fb = fc;
      if (kept == -1) fa /= 2;
      kept = -1;
    } else {
      a = c, fa = fc;
      if (kept == 1) fb /= 2;
      kept = 1;
    }
  }
  root.speed = c;
  const double near = 2 * tolerance * upper;
  root.atBracketEnd = std::abs(c - lower) <= near || std::abs(c - upper) <= near;
  return root;
}

}  // namespace beamrotor
