#include "problems/scenes/Mo10.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "elements/PointInertia.hpp"
#include "elements/Spring.hpp"

namespace beamrotor {

namespace {

constexpr double kPi = std::numbers::pi;

/// Extremes of f on [a, b] given its derivative g: sample finely enough that no two roots of g
/// of interest share a sub-interval (rate = the largest angular frequency present), bisect each
/// sign change of g, and include the end points.
template <class F, class G>
void scanExtremes(F f, G g, double a, double b, double rate, double& lo, double& hi) {
  const int n = std::max(8, int(std::ceil((b - a) * rate / 0.2)));  // 0.2 rad per sample
  auto take = [&](double t) {
    const double v = f(t);
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  };
  take(a);
  take(b);
  double tPrev = a, gPrev = g(a);
  for (int j = 1; j <= n; ++j) {
    const double t = a + (b - a) * j / n, gt = g(t);
    if ((gPrev < 0) != (gt < 0)) {
      double l = tPrev, r = t, gl = gPrev;
      for (int it = 0; it < 100 && r - l > 1e-15 * std::max(1.0, std::abs(r)); ++it) {
        const double m = 0.5 * (l + r), gm = g(m);
        if ((gm < 0) == (gl < 0)) {
          l = m;
          gl = gm;
        } else {
          r = m;
        }
      }
      take(0.5 * (l + r));
    }
    tPrev = t;
    gPrev = gt;
  }
}

}  // namespace

double Mo10Parameters::k() const {
  return std::sqrt(c * l * l / J);
}
double Mo10Parameters::mu() const {
  return muRatio * omega;
}
double Mo10Parameters::period() const {
  return 2 * kPi / omega;
}
double Mo10Parameters::t1() const {
  return period() - kPi / mu();
}
double Mo10Parameters::phi0() const {
  return a / l;
}

Mo10ClosedForm::Mo10ClosedForm(const Mo10Parameters& p, int cycles, Start start)
    : p_(p), k_(p.k()), mu_(p.mu()), T_(p.period()), t1_(p.t1()) {
  if (!(p.J > 0 && p.l > 0 && p.c > 0 && p.omega > 0 && p.muRatio > 0.5) || cycles < 1)
    throw std::invalid_argument(
        "MO-10: J, l, c, omega must be positive, mu > omega / 2 (the "
        "blow must fit in the cycle) and cycles >= 1");
  resonant_ = std::abs(k_ - mu_) <= std::sqrt(std::numeric_limits<double>::epsilon()) * mu_;

  if (start == Start::rest) {
    build(p.phi0(), 0, cycles);  // phi(0) = 0: x = phi + phi0 = phi0
    return;
  }
  build(0, 0, 1);
  const double x1 = shifted(0, T_, 0), v1 = shifted(0, T_, 1);
  const double C = std::cos(k_ * T_), S = std::sin(k_ * T_), det = 2 * (1 - C);
  if (!(det >= 1e-12))
    throw std::domain_error("MO-10: no periodic steady state at k = n omega (k T = " +
                            std::to_string(k_ * T_) + " rad, a multiple of 2 pi): resonance");
  cycles_.clear();
  build(((1 - C) * x1 + S / k_ * v1) / det, (-k_ * S * x1 + (1 - C) * v1) / det, cycles);
}

void Mo10ClosedForm::build(double x, double v, int cycles) {
  const double h = p_.H / p_.J;  // rad/s^2 per unit sin(mu tau)
  const double s1 = std::sin(k_ * t1_), c1 = std::cos(k_ * t1_);
  for (int i = 0; i < cycles; ++i) {
    Mo10Cycle c;
    // 1. Free swing from the cycle start: x = A1 sin k tau + A2 cos k tau.
    c.A1 = v / k_;
    c.A2 = x;
    // 2. The particular solution of x'' + k^2 x = h sin(mu tau).
    if (resonant_)
      c.D = -h / (2 * k_);
    else
      c.C1 = h / (k_ * k_ - mu_ * mu_);
    // 3. Continuity of x and x' at t1 fixes B1, B2: the homogeneous part carries what the
    // particular solution does not, P = x(t1) - xp(t1), Q = x'(t1) - xp'(t1).
    const double xt1 = c.A1 * s1 + c.A2 * c1, vt1 = k_ * (c.A1 * c1 - c.A2 * s1);
    const double P = xt1 - particular(c, t1_, 0), Q = vt1 - particular(c, t1_, 1);
    c.B1 = P * s1 + Q / k_ * c1;
    c.B2 = P * c1 - Q / k_ * s1;
    cycles_.push_back(c);
    // 4. The cycle's end state starts the next one.
    const int last = int(cycles_.size()) - 1;
    x = shifted(last, T_, 0);
    v = shifted(last, T_, 1);
  }
}

double Mo10ClosedForm::particular(const Mo10Cycle& c, double tau, int derivative) const {
  const double sk = std::sin(k_ * tau), ck = std::cos(k_ * tau);
  const double sm = std::sin(mu_ * tau), cm = std::cos(mu_ * tau);
  if (derivative == 0) return c.C1 * sm + c.C2 * cm + c.D * tau * ck;
  return mu_ * (c.C1 * cm - c.C2 * sm) + c.D * (ck - k_ * tau * sk);
}

double Mo10ClosedForm::shifted(int i, double tau, int derivative) const {
  const Mo10Cycle& c = cycles_[i];
  const double sk = std::sin(k_ * tau), ck = std::cos(k_ * tau);
  if (tau < t1_) return derivative == 0 ? c.A1 * sk + c.A2 * ck : k_ * (c.A1 * ck - c.A2 * sk);
  const double homogeneous = derivative == 0 ? c.B1 * sk + c.B2 * ck : k_ * (c.B1 * ck - c.B2 * sk);
  return homogeneous + particular(c, tau, derivative);
}

std::pair<int, double> Mo10ClosedForm::locate(double t, int cycles) const {
  const int last = cycles - 1;
  if (t < 0 || t > (last + 1) * T_ * (1 + 1e-12))
    throw std::out_of_range("MO-10 closed form: t = " + std::to_string(t) +
                            " s is outside the computed cycles");
  const int i = std::clamp(int(std::floor(t / T_)), 0, last);
  return {i, t - i * T_};
}

double Mo10ClosedForm::moment(double t) const {
  double tau = std::fmod(t, T_);
  if (tau < 0) tau += T_;
  return tau < t1_ ? 0.0 : p_.H * std::sin(mu_ * tau);
}

double Mo10ClosedForm::phi(double t) const {
  return phiOverCycles(int(cycles_.size()), t);
}

double Mo10ClosedForm::phiOverCycles(int cycles, double t) const {
  const auto [i, tau] = locate(t, std::clamp(cycles, 1, int(cycles_.size())));
  return shifted(i, tau, 0) - p_.phi0();
}

double Mo10ClosedForm::rate(double t) const {
  const auto [i, tau] = locate(t, int(cycles_.size()));
  return shifted(i, tau, 1);
}

void Mo10ClosedForm::extend(int cycles) {
  const int last = int(cycles_.size()) - 1;
  if (cycles <= last + 1) return;
  // The state at the end of the last cycle, as build() hands it to the next one.
  build(shifted(last, T_, 0), shifted(last, T_, 1), cycles - last - 1);
}

Mo10Extremes Mo10ClosedForm::extremes() const {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  const double fastest = std::max(k_, mu_);
  for (int i = 0; i < int(cycles_.size()); ++i) {
    auto f = [&](double tau) { return shifted(i, tau, 0); };
    auto g = [&](double tau) { return shifted(i, tau, 1); };
    // Phase by phase, so every scanned function is smooth; the blow's end is the cycle's end.
    scanExtremes(f, g, 0.0, std::nextafter(t1_, 0.0), k_, lo, hi);
    scanExtremes(f, g, t1_, T_, fastest, lo, hi);
  }
  Mo10Extremes e;
  e.phiMax = hi - p_.phi0();
  e.phiMin = lo - p_.phi0();
  e.amplitude = std::max(std::abs(e.phiMax), std::abs(e.phiMin));
  // c (l phi + a) = c l (phi + phi0).
  e.forceMax = p_.c * p_.l * hi;
  e.forceMin = p_.c * p_.l * lo;
  e.pressingForce = std::max(std::abs(e.forceMax), std::abs(e.forceMin));
  return e;
}

TimeFunction mo10BlowFactor(const Mo10Parameters& p) {
  const double mu = p.mu();
  return timefn::periodic(
      timefn::piecewise({{0.0, timefn::constant(0)}, {p.t1(), timefn::sine(1, mu)}}), p.period());
}

Mo10Model buildMo10Model(const Mo10Parameters& p) {
  Mo10Model m;
  m.node = m.model.addNode(Eigen::Vector3d::Zero());
  m.model.nameNode("body", m.node);
  // A body with J about every axis puts J on rz whatever the inertia axis.
  m.model.add<PointInertia>(m.node, DofSet{Dof::rz}, 0.0, p.J, p.J);
  const double kRot = p.c * p.l * p.l;  // N m/rad: force c l phi at arm l
  m.model.add<Spring>(NodeDof{m.node, Dof::rz}, kRot);
  if (p.a != 0) m.model.addLoad({m.node, Dof::rz, -kRot * p.phi0()});
  m.blows.name = "blows";
  m.blows.pattern.push_back({m.node, Dof::rz, p.H});
  m.blows.factor = mo10BlowFactor(p);
  return m;
}

}  // namespace beamrotor
