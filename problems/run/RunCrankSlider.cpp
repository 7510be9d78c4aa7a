#include "problems/run/RunCrankSlider.hpp"

#include <cmath>
#include <complex>
#include <numbers>
#include <stdexcept>

namespace beamrotor {

namespace {

constexpr double kCrankRadPerRpm = std::numbers::pi / 30;

/// |sum_j exp(i k theta_j)|: how much of an order-k term the cranks' phases leave.
double crankPhaseSum(const std::vector<double>& phases, int k) {
  std::complex<double> sum = 0;
  for (double theta : phases) sum += std::polar(1.0, k * theta);
  return std::abs(sum);
}

/// The mechanism at the first crank's angle phi (exact and approximate kinematics at the
/// crank speed) with its loads: reciprocating mass mRec and the rod's residual inertia (0
/// without masses). The sampled revolution and `crank PROPERTY at PHI deg` both read it.
CrankSample crankSampleAt(const DeckCrankSlider& d, double mRec, double residual, double phi) {
  const crank::Geometry& g = d.geometry;
  const double w = d.speed;
  CrankSample s;
  s.exact = crank::exact(g, phi, w);
  s.approximate = crank::approximate(g, phi, w);
  s.inertiaForce = -mRec * s.exact.a;
  for (double theta : d.phases) s.cranksForce += -mRec * crank::exact(g, phi + theta, w).a;
  s.rodCouple = residual != 0 ? crank::rodCorrectionCouple(residual, g, phi, w) : 0.0;
  return s;
}

CrankLambdaRow crankTableRow(double lambda) {
  // v_max / v_mean does not depend on r or omega: take r = lambda, l = 1, omega = 1.
  const crank::Geometry g = crank::makeGeometry(lambda, 1.0);
  CrankLambdaRow row;
  row.lambda = lambda;
  row.series = crank::seriesCoefficients(lambda);
  row.vRatio = crank::maxVelocity(g, 1.0) / crank::meanSliderSpeed(g, 1.0);
  row.kLambda = kCrankRadPerRpm * kCrankRadPerRpm * crank::maxAcceleration(g, 1.0) / g.r;
  return row;
}

}  // namespace

CrankSliderOutcome runCrankSlider(const DeckCrankSlider& d) {
  CrankSliderOutcome out;
  out.input = d;
  const crank::Geometry& g = d.geometry;
  const double w = d.speed;
  out.lambda = g.lambda();
  out.vMax = crank::maxVelocity(g, w);
  out.vMean = crank::meanSliderSpeed(g, w);
  out.aMax = crank::maxAcceleration(g, w);
  out.betaMax = std::asin(out.lambda);
  out.betaDotMax = crank::rodAngularVelocityAmplitude(out.lambda, w);
  out.betaDDotMax = crank::rodAngularAccelerationAmplitude(out.lambda, w);
  out.betaDDotMaxFirstOrder = crank::rodAngularAccelerationAmplitudeFirstOrder(out.lambda, w);
  out.series = crank::seriesCoefficients(out.lambda);

  double mRec = 0, residual = 0;
  if (d.masses) {
    out.reduced = crank::reduce(*d.masses, g);
    mRec = out.reduced->reciprocating;
    residual = d.masses->rod.residualInertia;
    const auto h = crank::reciprocatingInertiaHarmonics(mRec, g, w);
    static constexpr std::array<int, 4> kOrders{1, 2, 4, 6};
    for (std::size_t i = 0; i < h.size(); ++i) {
      out.harmonics[i] = std::abs(h[i].c);
      out.cranksHarmonics[i] = out.harmonics[i] * crankPhaseSum(d.phases, kOrders[i]);
    }
    out.rotatingForce = out.reduced->rotating * g.r * w * w;
    out.cranksRotating = out.rotatingForce * crankPhaseSum(d.phases, 1);
    out.momentMax = residual * out.betaDDotMax;
    out.momentMaxFirstOrder = residual * out.betaDDotMaxFirstOrder;
  }
  if (d.plungerDiameter > 0)
    out.delivery =
        crank::theoreticalDelivery(int(d.phases.size()), d.plungerDiameter, g.stroke(), w);

  for (int i = 0; i <= d.steps; ++i)
    out.samples.push_back(crankSampleAt(d, mRec, residual, 2 * std::numbers::pi * i / d.steps));
  for (double lambda : d.lambdas) out.table.push_back(crankTableRow(lambda));
  return out;
}

namespace {

/// The first crank's motion or load at crank angle phi: exact kinematics at the analysis' speed,
/// evaluated there (not read off the sampled revolution).
double measureCrankAtAngle(const std::string& p, double phi, const CrankSliderOutcome& c) {
  const double mRec = c.reduced ? c.reduced->reciprocating : 0;
  const double residual = c.input.masses ? c.input.masses->rod.residualInertia : 0;
  const CrankSample sample = crankSampleAt(c.input, mRec, residual, phi);
  const crank::State& s = sample.exact;
  if (p == "x") return s.x;
  if (p == "v") return s.v;
  if (p == "a") return s.a;
  if (p == "beta") return s.beta;
  if (p == "beta_dot") return s.betaDot;
  if (p == "beta_ddot") return s.betaDDot;
  if (!c.reduced) throw std::invalid_argument("'" + p + "' at a crank angle needs the masses");
  if (p == "force") return sample.inertiaForce;
  if (p == "cranks_force") return sample.cranksForce;
  if (p == "moment") return sample.rodCouple;
  throw std::invalid_argument("'" + p + "' is not a crank-slider quantity at a crank angle");
}

}  // namespace

double measureCrank(const Quantity& q, const CrankSliderOutcome& c) {
  const std::string& p = q.property;
  if (q.crankAngle) return measureCrankAtAngle(p, *q.crankAngle, c);
  if (q.lambda > 0) {
    for (const CrankLambdaRow& row : c.table) {
      if (std::abs(row.lambda - q.lambda) > 1e-12) continue;
      if (p == "A2") return row.series.A2;
      if (p == "A4") return row.series.A4;
      if (p == "A6") return row.series.A6;
      if (p == "v_ratio") return row.vRatio;
      return row.kLambda;
    }
    throw std::invalid_argument("'" + q.text + "': no table row at that lambda");
  }
  if (p == "lambda") return c.lambda;
  if (p == "v_max") return c.vMax;
  if (p == "v_mean") return c.vMean;
  if (p == "v_ratio") return c.vMax / c.vMean;
  if (p == "a_max") return c.aMax;
  if (p == "beta_max") return c.betaMax;
  if (p == "beta_dot_max") return c.betaDotMax;
  if (p == "beta_ddot_max") return c.betaDDotMax;
  if (p == "beta_ddot_max_first_order") return c.betaDDotMaxFirstOrder;
  if (p == "A2") return c.series.A2;
  if (p == "A4") return c.series.A4;
  if (p == "A6") return c.series.A6;
  if (p == "delivery") return c.delivery;
  if (!c.reduced) throw std::invalid_argument("'" + q.text + "' needs the drive's masses");
  if (p == "rotating_mass") return c.reduced->rotating;
  if (p == "reciprocating_mass") return c.reduced->reciprocating;
  if (p == "F1") return c.harmonics[0];
  if (p == "F2") return c.harmonics[1];
  if (p == "F_rotating") return c.rotatingForce;
  // One crank's first-order total: the rotating force and the reciprocating first harmonic
  // both turn once a revolution. The second order has the reciprocating term alone: the
  // rotating mass turns uniformly and has no second harmonic.
  if (p == "F1_total") return c.rotatingForce + c.harmonics[0];
  if (p == "F2_total") return c.harmonics[1];
  if (p == "cranks_F1") return c.cranksHarmonics[0];
  if (p == "cranks_F2") return c.cranksHarmonics[1];
  if (p == "cranks_rotating") return c.cranksRotating;
  if (p == "moment_max") return c.momentMax;
  if (p == "moment_max_first_order") return c.momentMaxFirstOrder;
  throw std::invalid_argument("'" + q.text + "' is not a crank-slider quantity");
}

}  // namespace beamrotor
