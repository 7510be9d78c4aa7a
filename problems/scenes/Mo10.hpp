// MO-10 impact mechanism body on springs (problems/scenes/README.md section 4): the closed-form
// response to a periodic train of half-sine blows, and the one-dof finite-element model of the same
// body.
//
//   J phi'' + c l^2 (phi + phi0) = M(t),   phi0 = a / l,   k^2 = c l^2 / J,
//   M(tau) = 0 on [0, t1), H sin(mu tau) on [t1, T), tau = t - (i - 1) T in cycle i,
//   T = 2 pi / omega, mu = 5 omega, t1 = T - pi / mu.
//
// Reading of the scene (problems/scenes/README.md section 4): because mu T = 10 pi, sin(mu t) is
// T-periodic, so cycle time and absolute time give the same M; mu t1 = 9 pi, so each blow is a
// NEGATIVE half-sine of amplitude H (it drives phi below zero). "From rest" is phi(0) = 0, phi'(0)
// = 0, which in the paper's form phi1 = A1 sin kt + A2 cos kt - phi0 is A1 = 0, A2 = phi0: with a
// preload the body starts at phi = 0 and swings about its equilibrium -phi0.
#pragma once

#include <vector>

#include "fem/model/Model.hpp"
#include "fem/transient/TimeLoad.hpp"

namespace beamrotor {

/// The body's data, SI units; defaults are the example values of problems/scenes/README.md section
/// 4 with c = 1e5 N/m.
struct Mo10Parameters {
  double J = 0.5;        ///< moment of inertia about the crank axis (kg m^2)
  double l = 0.1;        ///< spring arm (m)
  double a = 0;          ///< spring preload deflection (m)
  double H = 200;        ///< blow moment amplitude (N m)
  double omega = 37.18;  ///< blow frequency (rad/s): 1420 rpm through a gear of 4
  double c = 1e5;        ///< spring stiffness (N/m)
  double muRatio = 5;    ///< mu / omega

  double k() const;       ///< natural frequency sqrt(c l^2 / J) (rad/s)
  double mu() const;      ///< pulse frequency (rad/s)
  double period() const;  ///< T = 2 pi / omega (s)
  double t1() const;      ///< start of the blow within a cycle, T - pi / mu (s)
  double phi0() const;    ///< a / l (rad)
};

/// One cycle's constants in the paper's notation, in cycle time tau (s) (rad, rad/s ...):
///   [0, t1):  phi = A1 sin k tau + A2 cos k tau - phi0
///   [t1, T):  phi = B1 sin k tau + B2 cos k tau + C1 sin mu tau + C2 cos mu tau
///                   + D tau cos k tau - phi0
/// Off resonance C1 = H / (J (k^2 - mu^2)), C2 = D = 0; at k = mu C1 = C2 = 0 and
/// D = -H / (2 J k), the limit of the off-resonance solution as k -> mu.
struct Mo10Cycle {
  double A1 = 0, A2 = 0, B1 = 0, B2 = 0, C1 = 0, C2 = 0, D = 0;
};

/// Extremes over all computed cycles.
struct Mo10Extremes {
  double phiMax = 0, phiMin = 0;      ///< rad
  double amplitude = 0;               ///< max |phi| (rad)
  double forceMax = 0, forceMin = 0;  ///< spring force c (l phi + a) (N)
  double pressingForce = 0;           ///< max |c (l phi + a)| (N)
};

class Mo10ClosedForm {
 public:
  /// Where the motion starts: at rest (phi = phi' = 0), or in the periodic steady state, the
  /// state to which every cycle returns.
  enum class Start { rest, periodic };

  /// The solution over `cycles` cycles of the blow train. The periodic start solves
  /// (I - R) y0 = y1 for y = (phi + phi0, phi'): y1 the state after one cycle from y = 0 and
  /// R the free swing over T, [[cos kT, sin kT / k], [-k sin kT, cos kT]]; det(I - R) =
  /// 2 (1 - cos kT) vanishes at k = n omega, where no periodic state exists and the
  /// constructor throws std::domain_error (at 2 (1 - cos kT) < 1e-12, kT within 1e-6 of n 2 pi).
  Mo10ClosedForm(const Mo10Parameters& p, int cycles, Start start = Start::rest);

  /// Blow moment M(t) (N m).
  double moment(double t) const;
  /// Rotation phi (rad) and its rate (rad/s) for 0 <= t <= cycles T.
  double phi(double t) const;
  double rate(double t) const;
  /// phi(t) as the form of the first `cycles` cycles alone gives it, to the bit (t = k T is the
  /// end of cycle k there, not the start of k + 1), for 1 <= cycles <= cycles().size().
  double phiOverCycles(int cycles, double t) const;
  /// Computes the cycles after the last one up to `cycles` in all (none when it has as many):
  /// each the same, to the bit, as in a form built with `cycles` cycles at once.
  void extend(int cycles);
  /// True when k is within sqrt(machine epsilon) of mu and the resonant form is used: there the
  /// off-resonance form loses digits as eps / |k - mu| while the limit form errs by O(|k - mu|),
  /// so the switch point balances the two at ~1e-8.
  bool resonant() const { return resonant_; }
  const std::vector<Mo10Cycle>& cycles() const { return cycles_; }
  const Mo10Parameters& parameters() const { return p_; }
  /// Extremes of phi and of the spring force, located to round-off by bisection on phi'.
  Mo10Extremes extremes() const;

 private:
  /// phi + phi0 (derivative 0) or phi' (derivative 1) at cycle time tau of cycle i.
  double shifted(int i, double tau, int derivative) const;
  /// The blow's particular solution (C1, C2, D terms of c) or its derivative at tau.
  double particular(const Mo10Cycle& c, double tau, int derivative) const;
  /// Appends `cycles` cycles' constants, the first starting from x = phi + phi0 and v = phi'.
  void build(double x, double v, int cycles);
  /// Cycle index and cycle time of t among the first `cycles` cycles.
  std::pair<int, double> locate(double t, int cycles) const;

  Mo10Parameters p_;
  double k_, mu_, T_, t1_;
  bool resonant_ = false;
  std::vector<Mo10Cycle> cycles_;
};

/// The dimensionless blow train M(t) / H built from the time-function primitives: a periodic
/// repetition (period T) of a piecewise function, 0 then sin(mu tau).
TimeFunction mo10BlowFactor(const Mo10Parameters& p);

/// The body as a finite-element model: one node carrying rz only.
struct Mo10Model {
  Model model;
  int node = -1;
  TimeLoad blows;  ///< H times mo10BlowFactor on rz
};

/// Builds the model: a PointInertia J and a grounded rotational Spring c l^2 on rz. The dof
/// is phi itself, so the preload term c l^2 phi0 on the left of the equation becomes a
/// constant moment -c l^2 phi0 on the right, stored as the model's nodal load (a transient run
/// applies model loads at all times). The blows are a TimeLoad for TransientOptions::loads.
Mo10Model buildMo10Model(const Mo10Parameters& p);

}  // namespace beamrotor
