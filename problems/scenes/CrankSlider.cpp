// Crank-slider drive: implementation. The formulas are stated and derived in CrankSlider.hpp;
// here only the numerics that are not one-liners are explained.
#include "problems/scenes/CrankSlider.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <stdexcept>
#include <string>

namespace beamrotor::crank {

namespace {

constexpr double kPi = std::numbers::pi;

void require(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument("crank slider: " + what);
}

void check(const Geometry& g) {
  require(std::isfinite(g.r) && std::isfinite(g.l) && g.r > 0 && g.l > g.r,
          "need 0 < r < l (r = " + std::to_string(g.r) + " m, l = " + std::to_string(g.l) + " m)");
}

/// cos beta = sqrt(1 - lambda^2 sin^2 phi), positive for lambda < 1.
double cosBeta(double lambda, double phi) {
  const double s = lambda * std::sin(phi);
  return std::sqrt(1 - s * s);
}

/// Largest f over one revolution: sample at 720 points, then golden-section search in the
/// bracket of the best sample. f is smooth and its maxima are separated by far more than the
/// sampling step for lambda < 1, so the bracket holds exactly one maximum.
double maxOverRevolution(const std::function<double(double)>& f) {
  constexpr int n = 720;
  const double h = 2 * kPi / n;
  int best = 0;
  double fBest = f(0);
  for (int i = 1; i < n; ++i) {
    const double fi = f(i * h);
    if (fi > fBest) fBest = fi, best = i;
  }
  double lo = (best - 1) * h, hi = (best + 1) * h;
  const double invPhi = (std::sqrt(5.0) - 1) / 2;  // 1 / golden ratio
  double c = hi - invPhi * (hi - lo), d = lo + invPhi * (hi - lo);
  double fc = f(c), fd = f(d);
  // 80 reductions shrink the bracket by 0.618^80 ~ 2e-17 of 2h: past round-off in phi.
  for (int it = 0; it < 80; ++it) {
    if (fc > fd) {
      hi = d, d = c, fd = fc;
      c = hi - invPhi * (hi - lo), fc = f(c);
    } else {
      lo = c, c = d, fc = fd;
      d = lo + invPhi * (hi - lo), fd = f(d);
    }
  }
  return std::max(fBest, std::max(fc, fd));
}

}  // namespace

Geometry makeGeometry(double r, double l) {
  Geometry g{r, l};
  check(g);
  return g;
}

// 2. Exact kinematics -----------------------------------------------------------------------------

PhiDerivatives exactInPhi(const Geometry& g, double phi) {
  const double lam = g.lambda();
  const double sp = std::sin(phi), cp = std::cos(phi);
  const double cb = cosBeta(lam, phi);
  const double cb3 = cb * cb * cb;
  const double s2 = std::sin(2 * phi);
  PhiDerivatives d;
  d.beta = std::asin(lam * sp);
  d.dbeta = lam * cp / cb;
  d.d2beta = -lam * (1 - lam * lam) * sp / cb3;
  // l (1 - cos beta) written as l lambda^2 sin^2 phi / (1 + cos beta): no cancellation near the
  // dead centres, where 1 - cos beta ~ 1e-3 lambda^2 would lose digits.
  d.x = g.r * (1 - cp) + g.l * (lam * sp) * (lam * sp) / (1 + cb);
  d.dx = g.r * (sp + lam * s2 / (2 * cb));
  d.d2x = g.r * (cp + lam * std::cos(2 * phi) / cb + lam * lam * lam * s2 * s2 / (4 * cb3));
  return d;
}

State exact(const Geometry& g, double phi, double omega, double alpha) {
  check(g);
  const PhiDerivatives d = exactInPhi(g, phi);
  State s;
  s.phi = phi;
  s.x = d.x;
  s.v = d.dx * omega;
  s.a = d.d2x * omega * omega + d.dx * alpha;
  s.beta = d.beta;
  s.betaDot = d.dbeta * omega;
  s.betaDDot = d.d2beta * omega * omega + d.dbeta * alpha;
  return s;
}

State approximate(const Geometry& g, double phi, double omega) {
  check(g);
  const double lam = g.lambda();
  const double sp = std::sin(phi), cp = std::cos(phi);
  State s;
  s.phi = phi;
  s.x = g.r * (1 - cp + lam / 4 * (1 - std::cos(2 * phi)));
  s.v = g.r * omega * (sp + lam / 2 * std::sin(2 * phi));
  s.a = g.r * omega * omega * (cp + lam * std::cos(2 * phi));
  s.beta = lam * sp;
  s.betaDot = omega * lam * cp;
  s.betaDDot = -omega * omega * lam * sp;
  return s;
}

// 3. Harmonic series ------------------------------------------------------------------------------

SeriesCoefficients seriesCoefficients(double lambda) {
  const double l2 = lambda * lambda, l3 = l2 * lambda, l5 = l3 * l2;
  return {lambda + l3 / 4 + 15 * l5 / 128, l3 / 4 + 3 * l5 / 16, 9 * l5 / 128};
}

std::array<Harmonic, 4> accelerationHarmonics(double lambda) {
  const SeriesCoefficients A = seriesCoefficients(lambda);
  return {{{1, 1.0}, {2, A.A2}, {4, -A.A4}, {6, A.A6}}};
}

double evaluate(const std::array<Harmonic, 4>& series, double phi) {
  double sum = 0;
  for (const Harmonic& h : series) sum += h.c * std::cos(h.k * phi);
  return sum;
}

double seriesAcceleration(const Geometry& g, double phi, double omega) {
  check(g);
  return g.r * omega * omega * evaluate(accelerationHarmonics(g.lambda()), phi);
}

// 4. Peaks and means ------------------------------------------------------------------------------

double maxVelocity(const Geometry& g, double omega) {
  check(g);
  return std::abs(omega) *
         maxOverRevolution([&](double phi) { return std::abs(exactInPhi(g, phi).dx); });
}

double maxAcceleration(const Geometry& g, double omega) {
  check(g);
  return omega * omega *
         maxOverRevolution([&](double phi) { return std::abs(exactInPhi(g, phi).d2x); });
}

double meanSliderSpeed(const Geometry& g, double omega) {
  check(g);
  return 2 * g.r * std::abs(omega) / kPi;
}

double rodAngularVelocityAmplitude(double lambda, double omega) {
  return std::abs(omega * lambda);
}

double rodAngularAccelerationAmplitude(double lambda, double omega) {
  require(std::abs(lambda) < 1, "need |lambda| < 1");
  return omega * omega * std::abs(lambda) / std::sqrt(1 - lambda * lambda);
}

double rodAngularAccelerationAmplitudeFirstOrder(double lambda, double omega) {
  return omega * omega * std::abs(lambda);
}

// 5. Masses and inertia loads ---------------------------------------------------------------------

ReducedMasses reduce(const DriveMasses& m, const Geometry& g) {
  check(g);
  const RodMass& rod = m.rod;
  require(m.eccentricMass >= 0 && m.eccentricity >= 0 && m.sliderMass >= 0 && rod.mass >= 0 &&
              rod.comToBigEnd >= 0 && rod.comToSmallEnd >= 0,
          "masses and distances must be non-negative");
  const double span = rod.comToBigEnd + rod.comToSmallEnd;
  require(std::abs(span - g.l) <= 1e-6 * g.l,
          "the rod's centre-of-mass distances add up to " + std::to_string(span) +
              " m, not the rod length l = " + std::to_string(g.l) + " m");
  ReducedMasses r;
  r.eccentricAtPin = m.eccentricMass * m.eccentricity / g.r;
  r.rodBigEnd = rod.mass * rod.comToSmallEnd / span;
  r.rodSmallEnd = rod.mass * rod.comToBigEnd / span;
  r.rotating = r.eccentricAtPin + r.rodBigEnd;
  r.reciprocating = m.sliderMass + r.rodSmallEnd;
  return r;
}

double residualInertia(double Jg, double mass, double a, double b) {
  return Jg - mass * a * b;
}

std::array<Harmonic, 4> reciprocatingInertiaHarmonics(double reciprocatingMass, const Geometry& g,
                                                      double omega) {
  check(g);
  std::array<Harmonic, 4> h = accelerationHarmonics(g.lambda());
  const double scale = -reciprocatingMass * g.r * omega * omega;
  for (Harmonic& term : h) term.c *= scale;
  return h;
}

double rodCorrectionCouple(double residualInertia, const Geometry& g, double phi, double omega) {
  return -residualInertia * exact(g, phi, omega).betaDDot;
}

// 6. Balance and delivery -------------------------------------------------------------------------

std::array<double, 2> rotatingVectorSum(double amplitude, double phi, int order, int cranks) {
  require(cranks >= 1, "need at least one crank");
  std::array<double, 2> sum{0, 0};
  for (int j = 0; j < cranks; ++j) {
    const double theta = order * (phi + 2 * kPi * j / cranks);
    sum[0] += amplitude * std::cos(theta);
    sum[1] += amplitude * std::sin(theta);
  }
  return sum;
}

double reciprocatingForceSum(double reciprocatingMass, const Geometry& g, double phi, double omega,
                             int cranks) {
  require(cranks >= 1, "need at least one crank");
  double sum = 0;
  for (int j = 0; j < cranks; ++j)
    sum -= reciprocatingMass * exact(g, phi + 2 * kPi * j / cranks, omega).a;
  return sum;
}

double theoreticalDelivery(int plungers, double plungerDiameter, double stroke, double omega) {
  return plungers * (kPi * plungerDiameter * plungerDiameter / 4) * stroke * omega / (2 * kPi);
}

double Snt32::omega() const {
  return crankRpm * 2 * kPi / 60;
}

// 8. Pump-rod load source -------------------------------------------------------------------------

PumpRodSample pumpRodLoad(const PumpRodDrive& d, double phi, double omega,
                          double reciprocatingMass) {
  const Geometry g{d.r, d.l};
  check(g);
  const State s = exact(g, phi, omega);
  // eta = 2 r - x (crank on the left) or eta = x: the sign maps x-quantities to eta-quantities.
  const double sign = d.crankOnLeft ? -1.0 : 1.0;
  PumpRodSample out;
  out.phi = phi;
  out.eta = d.crankOnLeft ? g.stroke() - s.x : s.x;
  out.etaDot = sign * s.v;
  out.etaDDot = sign * s.a;
  // Inertia force along +eta is sign times the force along +x.
  out.forcing = reciprocatingInertiaHarmonics(reciprocatingMass, g, omega);
  for (Harmonic& h : out.forcing) h.c *= sign;
  return out;
}

double crankAngleAtStroke(const PumpRodDrive& d, double eta) {
  const Geometry g{d.r, d.l};
  check(g);
  require(eta >= 0 && eta <= g.stroke(), "eta = " + std::to_string(eta) +
                                             " m is outside the stroke [0, " +
                                             std::to_string(g.stroke()) + "] m");
  const double x = d.crankOnLeft ? g.stroke() - eta : eta;
  const double s = g.r + g.l - x;
  const double c = (s * s + g.r * g.r - g.l * g.l) / (2 * g.r * s);
  return std::acos(std::clamp(c, -1.0, 1.0));
}

double forceAt(const std::array<Harmonic, 4>& forcing, double omega, double t) {
  return evaluate(forcing, omega * t);
}

}  // namespace beamrotor::crank
