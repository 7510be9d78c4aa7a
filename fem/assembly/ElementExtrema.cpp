#include "fem/assembly/ElementExtrema.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>

#include "fem/assembly/Polynomial.hpp"
#include "fem/assembly/Recovery.hpp"
#include "fem/assembly/SolutionPolynomials.hpp"
#include "fem/model/ShearStress.hpp"

namespace beamrotor {

namespace {

/// Appends the zeros in [0, 1] of c0 + c1 s + c2 s^2 (c2 != 0) and its vertex there, in closed
/// form: q = -(c1 + sign(c1) sqrt(c1^2 - 4 c0 c2)) / 2 gives the zeros q / c2 and c0 / q without
/// the cancellation of the textbook formula (Press et al., Numerical Recipes, 3rd ed., 5.6). The
/// vertex -c1 / (2 c2) is the zero of the derivative: a double zero, or a near-double one that
/// round-off pushed to a slightly negative discriminant, lies there.
template <class Places>
void quadraticZeros(double c0, double c1, double c2, Places& out) {
  const auto keep = [&](double s) {
    if (s >= 0 && s <= 1) out.push_back(s);
  };
  keep(-c1 / (2 * c2));
  const double discriminant = c1 * c1 - 4 * c0 * c2;
  if (!(discriminant > 0)) return;  // also NaN
  const double q = -0.5 * (c1 + std::copysign(std::sqrt(discriminant), c1));
  keep(q / c2);
  if (q != 0) keep(c0 / q);
}

/// p and its derivative at s (Horner, both at once), and the bound on the round-off of the
/// value, 2 n eps sum |c_k| s^k for degree n (Higham, Accuracy and Stability of Numerical
/// Algorithms, 2nd ed., 5.1).
struct HornerValue {
  double value = 0, slope = 0, roundOff = 0;
};
HornerValue valueAndSlope(const Polynomial& p, double s) {
  HornerValue h;
  double size = 0;
  for (auto c = p.rbegin(); c != p.rend(); ++c) {
    h.slope = h.slope * s + h.value;
    h.value = h.value * s + *c;
    size = size * std::abs(s) + std::abs(*c);
  }
  h.roundOff = 2 * double(p.size()) * std::numeric_limits<double>::epsilon() * size;
  return h;
}

/// The zero of p in [lo, hi], where p is monotone and changes sign (p(lo) < 0 when rising):
/// Newton's method kept inside the shrinking bracket, a bisection whenever its step would
/// leave it or would not halve the step before last (Press et al., Numerical Recipes, rtsafe),
/// so it never converges slower than bisection. Ends where the value is within its own
/// round-off of zero (no place nearer is known in double precision), when the step is below
/// round-off of s, or when the bracket holds no double between its ends: a few steps where
/// bisection took about 53.
double zeroInBracket(const Polynomial& p, double lo, double hi, bool rising) {
  double s = 0.5 * (lo + hi), stepBeforeLast = hi - lo, step = stepBeforeLast;
  for (int i = 0; i < 200; ++i) {
    const HornerValue h = valueAndSlope(p, s);
    if (std::abs(h.value) <= h.roundOff) return s;
    if (std::isnan(h.value)) break;
    ((h.value < 0) == rising ? lo : hi) = s;
    double next = s - h.value / h.slope;
    if (!(next > lo && next < hi) || std::abs(next - s) > 0.5 * std::abs(stepBeforeLast))
      next = 0.5 * (lo + hi);  // out of the bracket, not converging fast, or a zero slope
    if (next <= lo || next >= hi) break;  // lo and hi adjacent doubles
    stepBeforeLast = step;
    step = next - s;
    const bool settled = std::abs(step) <= 4 * std::numeric_limits<double>::epsilon() * s;
    s = next;
    if (settled) break;
  }
  return s;
}

template <class Places>
void collectZeros(Polynomial p, Places& out);

/// collectZeros of p (degree 3 or more, its leading coefficient not 0) with `knots` holding
/// the ends 0 and 1 and room for the zeros of p's derivatives.
template <class Knots, class Places>
void zerosBetweenKnots(const Polynomial& p, Knots& knots, Places& out) {
  collectZeros(derivativeOf(p), knots);
  std::sort(knots.begin(), knots.end());
  knots.resize(std::size_t(std::unique(knots.begin(), knots.end()) - knots.begin()));
  for (std::size_t k = 1; k + 1 < knots.size(); ++k) out.push_back(knots[k]);
  double atLo = valueAt(p, knots[0]);
  if (atLo == 0) out.push_back(knots[0]);
  for (std::size_t k = 0; k + 1 < knots.size(); ++k) {
    const double lo = knots[k], hi = knots[k + 1];
    const double atHi = valueAt(p, hi);
    if (atHi == 0) out.push_back(hi);
    if ((atLo < 0 && atHi > 0) || (atLo > 0 && atHi < 0))  // not NaN
      out.push_back(zeroInBracket(p, lo, hi, atLo < 0));
    atLo = atHi;
  }
}

/// Appends the zeros of p in [0, 1] and those of its derivatives. Degrees 1 and 2 in closed
/// form; above, between consecutive zeros of p' (found the same way, down to the closed forms)
/// the polynomial is monotone, so each sign change there holds exactly one zero, found by
/// zeroInBracket; a zero of even multiplicity is a zero of p' and so already among them. The
/// knots are kept once each, so a degree-n polynomial appends at most about n^2 places
/// (ZeroPlaces holds those of degree 10; a cubic's, at most five, are held in a smaller list,
/// which costs less to set up: the envelope along the members asks for millions of them).
template <class Places>
void collectZeros(Polynomial p, Places& out) {
  while (!p.empty() && p.back() == 0) p.pop_back();
  if (p.size() < 2) return;  // a constant: no isolated zero
  if (p.size() == 2) {
    const double s = -p[0] / p[1];
    if (s >= 0 && s <= 1) out.push_back(s);
    return;
  }
  if (p.size() == 3) return quadraticZeros(p[0], p[1], p[2], out);
  if (p.size() == 4) {
    InPlaceDoubles<8> knots{0, 1};
    return zerosBetweenKnots(p, knots, out);
  }
  ZeroPlaces knots{0, 1};
  zerosBetweenKnots(p, knots, out);
}

/// The largest of value(s) over the candidate places; NaN as soon as one value is NaN.
template <class Places, class Value>
BeamPeak largestAt(int element, const Places& places, Value value) {
  BeamPeak best{element, 0, -std::numeric_limits<double>::infinity()};
  for (double s : places) {
    const double v = value(s);
    if (std::isnan(v)) return {element, s, v};
    if (v > best.value) best = {element, s, v};
  }
  return best;
}

}  // namespace

std::vector<double> zerosInUnitInterval(const std::vector<double>& c) {
  std::vector<double> out;
  collectZeros(Polynomial(c.begin(), c.end()), out);
  return out;
}

void appendZeros(const Polynomial& p, ZeroPlaces& out) {
  collectZeros(p, out);
}

void appendZeros(const Polynomial& p, std::vector<double>& out) {
  collectZeros(p, out);
}

ElementPeaks elementPeaks(const LineElement& element, const SectionForceSeries& forces) {
  const auto series = [&](double SectionForces::*f) {
    Polynomial p;
    for (const SectionForces& c : forces.c) p.push_back(c.*f);
    return p;
  };
  const Polynomial N = series(&SectionForces::N), Vy = series(&SectionForces::Vy),
                   Vz = series(&SectionForces::Vz), My = series(&SectionForces::My),
                   Mz = series(&SectionForces::Mz);
  const Section& section = element.section();

  // 1. Bending moment |M| = sqrt(P), P = My^2 + Mz^2: at an end or where P' = 0.
  const Polynomial P = combination(1, productOf(My, My), 1, productOf(Mz, Mz));
  const Polynomial dP = derivativeOf(P);
  ZeroPlaces momentAt{0, 1};
  collectZeros(dP, momentAt);

  // 2. Shear stress k |V| / A, |V|^2 = Vy^2 + Vz^2 (a polynomial): at an end or where its
  //    derivative vanishes.
  ZeroPlaces shearAt{0, 1};
  collectZeros(derivativeOf(combination(1, productOf(Vy, Vy), 1, productOf(Vz, Vz))), shearAt);

  // 3. Normal stress (maxNormalStress): the largest over the fibres of |sigma|, sigma = c + a y
  //    + b z with c = N/A, a = -Mz/Iz, b = My/Iy, all polynomials in s. At a sharp fibre
  //    |c + a y + b z| is smooth between the zeros of its argument, where a kink can only be a
  //    minimum, so its maximum is at an end or where the argument's derivative vanishes. Over an
  //    arc of radius r about (y, z) the largest is +-p + r sqrt(P), p = c + a y + b z, P = a^2 +
  //    b^2, stationary where +-p' = -r P' / (2 sqrt(P)), i.e. at zeros of 4 p'^2 P - r^2 P'^2
  //    (squared: both signs), or, while the gradient points outside the arc, at an end of the
  //    arc (a sharp point; the two pieces join with equal slopes). Candidates are evaluated
  //    with the true formula, so extra ones cost nothing but time.
  const Polynomial c = combination(1 / section.A, N, 0, {}),
                   a = combination(-1 / section.Iz, Mz, 0, {}),
                   b = combination(1 / section.Iy, My, 0, {});
  const auto linearAt = [&](double y, double z) {
    return combination(1, c, 1, combination(y, a, z, b));
  };
  std::vector<double> stressAt(momentAt.begin(), momentAt.end());
  collectZeros(N, stressAt);
  const Polynomial gradient = combination(1, productOf(a, a), 1, productOf(b, b));
  const Polynomial dGradient = derivativeOf(gradient);
  for (const StressFibre& fibre : section.fibres) {
    const Polynomial dp = derivativeOf(linearAt(fibre.y, fibre.z));
    collectZeros(dp, stressAt);
    if (fibre.radius == 0) continue;
    collectZeros(combination(4, productOf(productOf(dp, dp), gradient),
                             -fibre.radius * fibre.radius, productOf(dGradient, dGradient)),
                 stressAt);
    for (double end : {fibre.from, fibre.from + fibre.sweep})
      collectZeros(derivativeOf(linearAt(fibre.y + fibre.radius * std::cos(end),
                                         fibre.z + fibre.radius * std::sin(end))),
                   stressAt);
  }

  return {largestAt(-1, stressAt, [&](double s) { return maxNormalStress(section, forces.at(s)); }),
          largestAt(-1, shearAt, [&](double s) { return maxShearStress(section, forces.at(s)); }),
          largestAt(-1, momentAt, [&](double s) {
            const SectionForces f = forces.at(s);
            return std::hypot(f.My, f.Mz);
          })};
}

std::vector<ElementPeaks> elementPeaks(const LoadedSolution& solution) {
  std::vector<ElementPeaks> out;
  const auto& elements = solution.model->elements();
  for (int i = 0; i < int(elements.size()); ++i) {
    const LineElement* line = asLine(elements[i]);
    if (!line) continue;
    ElementPeaks p = elementPeaks(*line, solution.forceSeries(i));
    p.stress.element = p.shear.element = p.moment.element = i;
    out.push_back(p);
  }
  return out;
}

namespace {

/// Upper bounds of an element's three peaks over the whole element from upper bounds of its
/// |N|, |Vy|, |Vz|, |My|, |Mz| along it (`bounds`: ElementBounds::forces): with every fibre
/// within (|y| + r, |z| + r) of the axis, |sigma| <= |N| / A + |Mz| / Iz max(|y| + r) + |My| /
/// Iy max(|z| + r) (fibreSupport is at most |dy| (|y| + r) + |dz| (|z| + r)); the shear stress
/// as maxShearStress of the bounds (it grows with |Vy| and |Vz|); the moment hypot of the
/// bounds. The values elementPeaks computes carry round-off of a few eps of these (a cubic's
/// Horner value errs by at most 6 eps sum |a_k| <= 6 eps 27 max |b_i|), far below the 1e-9
/// margin the caller adds. NaN (never below anything) for a section without fibres, whose
/// stress is NaN.
std::array<double, 3> elementBounds(const Section& section, const SectionForces& bounds) {
  double stress = std::numeric_limits<double>::quiet_NaN();
  if (!section.fibres.empty()) {
    double y = 0, z = 0;
    for (const StressFibre& fibre : section.fibres) {
      y = std::max(y, std::abs(fibre.y) + fibre.radius);
      z = std::max(z, std::abs(fibre.z) + fibre.radius);
    }
    stress = bounds.N / section.A + bounds.Mz / section.Iz * y + bounds.My / section.Iy * z;
  }
  return {stress, maxShearStress(section, SectionForces{.Vy = bounds.Vy, .Vz = bounds.Vz}),
          std::hypot(bounds.My, bounds.Mz)};
}

/// The three kinds, in the order of elementBounds.
constexpr BeamPeak ElementPeaks::*kKinds[3] = {&ElementPeaks::stress, &ElementPeaks::shear,
                                               &ElementPeaks::moment};

/// How many elements of each kind, those of the largest bounds, give the values the others'
/// bounds are compared with: their peaks are computed first.
constexpr std::size_t kSeedElements = 4;

}  // namespace

std::vector<ElementPeaks> peaksThatCanGovern(const LoadedSolution& solution) {
  const auto& elements = solution.model->elements();
  // 1. Each line element's bounds of the three kinds: from the solution's polynomials' bounds
  //    when it carries them (of a combination, its cases' weighted: no sum formed), else from
  //    its resultants.
  std::vector<int> lines;
  std::vector<std::array<double, 3>> bounds(elements.size());
  for (int i = 0; i < int(elements.size()); ++i) {
    const LineElement* line = asLine(elements[i]);
    if (!line) continue;
    lines.push_back(i);
    bounds[i] = elementBounds(line->section(), solution.polynomials
                                                   ? solution.polynomials->bounds(i).forces
                                                   : resultantBounds(solution.forceSeries(i)));
  }
  // 2. The peaks of the few elements of each kind's largest bounds (a bound that is not a
  //    number first): the largest peak of a kind is at least theirs, the seed. Kept, to be
  //    computed once.
  const auto computed = [&](int i) {
    ElementPeaks p = elementPeaks(*asLine(elements[i]), solution.forceSeries(i));
    p.stress.element = p.shear.element = p.moment.element = i;
    return p;
  };
  std::vector<std::pair<int, ElementPeaks>> seeded;
  const auto seededPeaks = [&](int i) -> const ElementPeaks* {
    for (const auto& [element, p] : seeded)
      if (element == i) return &p;
    return nullptr;
  };
  std::array<double, 3> seed;
  seed.fill(-std::numeric_limits<double>::infinity());
  std::vector<int> first;
  for (int k = 0; k < 3; ++k) {
    const auto key = [&](int i) {
      return std::isnan(bounds[i][k]) ? std::numeric_limits<double>::infinity() : bounds[i][k];
    };
    first = lines;
    const std::size_t count = std::min(kSeedElements, first.size());
    std::partial_sort(first.begin(), first.begin() + std::ptrdiff_t(count), first.end(),
                      [&](int a, int b) { return key(a) > key(b); });
    for (std::size_t j = 0; j < count; ++j) {
      const ElementPeaks* p = seededPeaks(first[j]);
      if (!p) p = &seeded.emplace_back(first[j], computed(first[j])).second;
      for (int m = 0; m < 3; ++m) {
        const double v = (p->*kKinds[m]).value;
        if (v > seed[m]) seed[m] = v;
      }
    }
  }
  // 3. The peaks of every element that some kind's bound does not keep below its seed.
  std::vector<ElementPeaks> out;
  for (int i : lines) {
    bool below = true;
    for (int k = 0; k < 3; ++k) below = below && bounds[i][k] * (1 + 1e-9) < seed[k];
    if (below) continue;
    const ElementPeaks* p = seededPeaks(i);
    out.push_back(p ? *p : computed(i));
  }
  return out;
}

std::optional<BeamPeak> largestPeak(const std::vector<ElementPeaks>& peaks,
                                    BeamPeak ElementPeaks::*kind) {
  std::optional<BeamPeak> best;
  for (const ElementPeaks& p : peaks) {
    const BeamPeak& candidate = p.*kind;
    if (std::isnan(candidate.value)) return candidate;
    if (!best || candidate.value > best->value) best = candidate;
  }
  return best;
}

}  // namespace beamrotor
