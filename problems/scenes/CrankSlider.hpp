// Crank-slider drive: exact and harmonic-series kinematics, reduced masses and inertia loads,
// and a load source for decks (problems/scenes/README.md section 3, the SNT-32 triplex plunger
// pump; section 1, the pump rod whose stroke position eta the drive sets).
//
//                 B (crank pin)
//                / `-.
//             r /     `-.  l (connecting rod)
//              / phi     `-.  beta
//   crank axis O---------------C==[slider]      line of stroke through O and C
//
// Conventions (SI throughout):
// - phi is the crank angle (rad) from the outer dead centre, where crank and rod lie in line and
//   the slider is farthest from the crank axis; phi = omega t for a uniformly turning crank.
// - x is the slider's displacement (m) from the outer dead centre, positive towards the crank
//   axis, so x in [0, 2 r]; v, a its rate and second rate.
// - beta is the rod's angle (rad) to the line of stroke, sin beta = lambda sin phi, lambda = r/l.
// With these, x = r (1 - cos phi) + l (1 - cos beta), and the approximate forms carry a PLUS
// sign: v ~ +r omega (sin phi + lambda/2 sin 2 phi), a ~ +r omega^2 (cos phi + lambda cos 2 phi).
// The paper prints both with a leading minus, which is the opposite positive direction (or the
// inertia force per unit mass); it is not consistent with its own x.
//
// Sources of the formulas: the crank-slider kinematics and its Fourier series are the classical
// ones (e.g. Artobolevsky, "Theory of Mechanisms and Machines"; Shigley & Uicker, "Theory of
// Machines and Mechanisms", chapter on the dynamics of reciprocating engines); each function
// below states its formula and its derivation where it is not a textbook line.
#pragma once

#include <array>

namespace beamrotor::crank {

// 1. Geometry ------------------------------------------------------------------------------------

/// Crank radius r and connecting-rod length l between pin centres, both in m.
struct Geometry {
  double r = 0;  ///< crank radius (m); the stroke is 2 r
  double l = 0;  ///< rod length between the crank-pin and slider-pin centres (m)

  /// lambda = r / l (dimensionless).
  double lambda() const { return r / l; }
  /// Slider stroke 2 r (m).
  double stroke() const { return 2 * r; }
};

/// Checked constructor: throws std::invalid_argument unless 0 < r < l (a crank that turns
/// through a full revolution) and both are finite.
Geometry makeGeometry(double r, double l);

// 2. Exact kinematics ----------------------------------------------------------------------------

/// Position-level quantities and their derivatives with respect to the crank angle phi
/// (per rad, per rad^2): the kinematics independent of how the crank turns.
struct PhiDerivatives {
  double x = 0;       ///< slider displacement (m)
  double dx = 0;      ///< dx/dphi (m/rad)
  double d2x = 0;     ///< d2x/dphi2 (m/rad^2)
  double beta = 0;    ///< rod angle (rad)
  double dbeta = 0;   ///< dbeta/dphi (dimensionless)
  double d2beta = 0;  ///< d2beta/dphi2 (1/rad)
};

/// Exact derivatives in phi, with cos beta = sqrt(1 - lambda^2 sin^2 phi):
///   x       = r (1 - cos phi) + l (1 - cos beta)
///   dx      = r (sin phi + lambda sin 2phi / (2 cos beta))          = r sin(phi + beta) / cos beta
///   d2x     = r (cos phi + lambda cos 2phi / cos beta + lambda^3 sin^2 2phi / (4 cos^3 beta))
///   dbeta   = lambda cos phi / cos beta
///   d2beta  = -lambda (1 - lambda^2) sin phi / cos^3 beta
/// (each line the derivative of the one before; the tests check them by finite differences).
PhiDerivatives exactInPhi(const Geometry& g, double phi);

/// Kinematic state of the slider and the rod at one instant.
struct State {
  double phi = 0;       ///< crank angle (rad)
  double x = 0;         ///< slider displacement (m), see the conventions above
  double v = 0;         ///< slider velocity (m/s)
  double a = 0;         ///< slider acceleration (m/s^2)
  double beta = 0;      ///< rod angle (rad)
  double betaDot = 0;   ///< rod angular velocity (rad/s)
  double betaDDot = 0;  ///< rod angular acceleration (rad/s^2)
};

/// Exact state for crank speed omega (rad/s) and crank angular acceleration alpha (rad/s^2,
/// 0 for uniform rotation), by the chain rule: v = x' omega, a = x'' omega^2 + x' alpha, and
/// likewise for beta. For alpha = 0: betaDot = omega lambda cos phi / cos beta and
/// betaDDot = -omega^2 lambda (1 - lambda^2) sin phi / cos^3 beta.
State exact(const Geometry& g, double phi, double omega, double alpha = 0);

/// Two-term (first-order in lambda) approximation, uniform rotation:
///   x ~ r (1 - cos phi + lambda/4 (1 - cos 2phi)), v ~ r omega (sin phi + lambda/2 sin 2phi),
///   a ~ r omega^2 (cos phi + lambda cos 2phi), beta ~ lambda sin phi,
///   betaDot ~ omega lambda cos phi, betaDDot ~ -omega^2 lambda sin phi.
/// Errors are O(lambda^3) r for x, v, a and O(lambda^3) for beta.
State approximate(const Geometry& g, double phi, double omega);

// 3. Harmonic series of the slider acceleration --------------------------------------------------

/// Coefficients of a = r omega^2 (cos phi + A2 cos 2phi - A4 cos 4phi + A6 cos 6phi) + O(lambda^7).
/// Derivation: l (1 - cos beta) = r (lambda s/2 + lambda^3 s^2/8 + lambda^5 s^3/16 + ...) with
/// s = sin^2 phi (binomial series of sqrt(1 - lambda^2 s)); the power-reduction formulas for
/// sin^2, sin^4, sin^6 give x / r = const - cos phi - A2/4 cos 2phi + A4/16 cos 4phi
/// - A6/36 cos 6phi + O(lambda^7), and d2/dphi2 gives the signs above. At phi = 0 the series sums
/// to 1 + lambda exactly (the lambda^5 terms cancel), as the exact form does.
struct SeriesCoefficients {
  double A2 = 0;  ///< lambda + lambda^3/4 + 15 lambda^5/128
  double A4 = 0;  ///< lambda^3/4 + 3 lambda^5/16
  double A6 = 0;  ///< 9 lambda^5/128
};
SeriesCoefficients seriesCoefficients(double lambda);

/// One term c cos(k phi) of a harmonic series; what c measures is stated where it is returned.
struct Harmonic {
  int k = 0;
  double c = 0;
};

/// The slider acceleration per unit r omega^2 as cos(k phi) coefficients, k = 1, 2, 4, 6:
/// {1, A2, -A4, A6} (dimensionless).
std::array<Harmonic, 4> accelerationHarmonics(double lambda);

/// Sum c_k cos(k phi) of a series (same units as the c_k).
double evaluate(const std::array<Harmonic, 4>& series, double phi);

/// Slider acceleration (m/s^2) from the series through lambda^5, uniform rotation.
double seriesAcceleration(const Geometry& g, double phi, double omega);

// 4. Peaks and means over a revolution (uniform rotation) -----------------------------------------

/// Largest |v| over a revolution (m/s) from the exact kinematics, located by sampling and
/// golden-section refinement (the value is accurate to round-off: it is flat at the maximum).
/// For small lambda it is close to r omega (1 + lambda^2/2).
double maxVelocity(const Geometry& g, double omega);

/// Largest |a| over a revolution (m/s^2), exact kinematics, found the same way. For lambda < 1
/// it is r omega^2 (1 + lambda), at the outer dead centre.
double maxAcceleration(const Geometry& g, double omega);

/// Mean slider speed (m/s): path 4 r per revolution over the period 2 pi / omega, = 2 r omega / pi.
double meanSliderSpeed(const Geometry& g, double omega);

/// Largest |betaDot| (rad/s): omega lambda exactly, at the dead centres (|cos phi| <= cos beta).
double rodAngularVelocityAmplitude(double lambda, double omega);

/// Largest |betaDDot| (rad/s^2): exactly omega^2 lambda / sqrt(1 - lambda^2), at phi = pi/2
/// (|betaDDot| grows monotonically with |sin phi|).
double rodAngularAccelerationAmplitude(double lambda, double omega);

/// First-order (two-term) estimate of the same amplitude: omega^2 lambda (rad/s^2).
double rodAngularAccelerationAmplitudeFirstOrder(double lambda, double omega);

// 5. Masses and inertia loads --------------------------------------------------------------------

/// Connecting rod: mass and where its centre of mass lies between the pin centres.
struct RodMass {
  double mass = 0;           ///< kg
  double comToBigEnd = 0;    ///< distance from the centre of mass to the crank-pin (big) end (m)
  double comToSmallEnd = 0;  ///< distance from the centre of mass to the slider-pin (small) end (m)
  /// Residual moment of inertia about the centre of mass that the two-point model misses (kg m^2):
  /// J_G - m a b, see residualInertia().
  double residualInertia = 0;
};

/// Masses of the drive as built.
struct DriveMasses {
  double eccentricMass = 0;  ///< crank or eccentric (kg)
  double eccentricity = 0;   ///< distance of its centre of mass from the crank axis (m)
  double sliderMass = 0;     ///< slider set: crosshead, plunger and what moves with them (kg)
  RodMass rod;
};

/// The drive reduced to a mass at the crank pin and a mass at the slider pin.
struct ReducedMasses {
  double eccentricAtPin = 0;  ///< eccentric reduced to the crank pin, m_e e / r (kg)
  double rodBigEnd = 0;       ///< rod's share at the crank pin, m b / (a + b) (kg)
  double rodSmallEnd = 0;     ///< rod's share at the slider pin, m a / (a + b) (kg)
  double rotating = 0;        ///< eccentricAtPin + rodBigEnd (kg)
  double reciprocating = 0;   ///< sliderMass + rodSmallEnd (kg)
};

/// Reduction by equal static moments: the eccentric keeps its centrifugal force
/// (m_e e omega^2 = m_pin r omega^2), and the rod is split into two point masses at its pins
/// with the same mass and centre of mass (lever rule: the share at one end is proportional to
/// the distance of the centre of mass from the OTHER end; a = comToBigEnd, b = comToSmallEnd).
/// Throws std::invalid_argument if a + b differs from g.l by more than 1e-6 relative or a value
/// is negative.
ReducedMasses reduce(const DriveMasses& m, const Geometry& g);

/// Residual inertia J_G - m a b (kg m^2): the two-point rod has moment of inertia
/// m_A a^2 + m_B b^2 = m a b about the centre of mass, so this is the part of the rod's inertia
/// the point masses do not carry (classical two-mass connecting-rod model with its correction
/// couple; e.g. Shigley & Uicker, "equivalent masses" of the connecting rod).
double residualInertia(double Jg, double mass, double a, double b);

/// Inertia force of the reciprocating mass along +x, F = -m_rec a, as cos(k phi) amplitudes (N)
/// for k = 1, 2, 4, 6: -m_rec r omega^2 {1, A2, -A4, A6}. The first two magnitudes are the
/// "first and second harmonics" m_rec r omega^2 and (to first order) m_rec r omega^2 lambda.
std::array<Harmonic, 4> reciprocatingInertiaHarmonics(double reciprocatingMass, const Geometry& g,
                                                      double omega);

/// Correction couple on the rod (N m, same sense as beta): -residualInertia * betaDDot, exact
/// kinematics, uniform rotation. Its amplitude is residualInertia times
/// rodAngularAccelerationAmplitude().
double rodCorrectionCouple(double residualInertia, const Geometry& g, double phi, double omega);

// 6. Multi-crank balance and delivery ------------------------------------------------------------

/// Vector sum (x, y) of the order-k rotating vectors of n cranks equally spaced by 2 pi / n:
/// amplitude * sum_j (cos k theta_j, sin k theta_j), theta_j = phi + 2 pi j / n. Order 1 with
/// amplitude m_rot r omega^2 is the resultant of the rotating masses' centrifugal forces; order 2
/// is the resultant of the second-order "phantom crank" vectors. Both vanish for n = 3; orders
/// that are multiples of n add up to n * amplitude.
std::array<double, 2> rotatingVectorSum(double amplitude, double phi, int order, int cranks = 3);

/// Resultant (N) of the exact reciprocating inertia forces -m_rec a(theta_j) of n parallel
/// cylinders with cranks 2 pi / n apart. For n = 3 only the orders 3, 6, ... survive:
/// -3 m_rec r omega^2 A6 cos 6 phi + O(lambda^7).
double reciprocatingForceSum(double reciprocatingMass, const Geometry& g, double phi, double omega,
                             int cranks = 3);

/// Theoretical delivery (m^3/s) of a pump with z single-acting plungers of diameter d (m),
/// stroke s (m), crank speed omega (rad/s): Q = z (pi d^2 / 4) s omega / (2 pi).
double theoreticalDelivery(int plungers, double plungerDiameter, double stroke, double omega);

// 7. The SNT-32 data (problems/scenes/README.md section 3)
// -------------------------------------------------------

/// Data of the SNT-32 drive as printed (the published results are in the tests).
struct Snt32 {
  Geometry geometry{0.0188, 0.288};  ///< r, l (m); the paper prints lambda = 0.065
  double printedLambda = 0.065;      ///< lambda as the paper rounds it (r/l = 0.06528)
  double crankRpm = 1470.0 / 2.5;    ///< motor 1470 rpm through a gear of 2.5: 588 rpm
  double printedOmega = 62;          ///< the paper's rounded crank speed (rad/s); 588 rpm = 61.58
  int plungers = 3;
  double plungerDiameter = 0.045;  ///< m
  /// Masses. The rod's centre of mass is 0.040 m from the big end and 0.248 m from the small
  /// end: the only assignment that gives the published 25.27 kg / 17.79 kg (the other gives
  /// 12.27 kg / 30.79 kg).
  DriveMasses masses{24.1, 0.00762, 15.29, {18.0, 0.040, 0.248, 0.93}};

  /// 588 rpm in rad/s (61.575).
  double omega() const;
};

// 8. Load source for a deck: the pump rod of problems/scenes/README.md section 1
// ---------------------------------

/// The drive of the pump rod. eta in [0, 2 r] is the rod's stroke position of section 1
/// (eta = 0 extreme left, eta = 2 r extreme right; the deck's 0.4 m stroke is r = 0.2).
struct PumpRodDrive {
  double r = 0.2;  ///< crank radius (m)
  double l = 0;    ///< connecting-rod length (m); required, > r
  /// True (default): the crankshaft lies left of the crosshead (the power end on the crosshead
  /// side of the rod), so the extreme right eta = 2 r is the outer dead centre and
  /// eta = 2 r - x. False: eta = x (the extreme left is the outer dead centre).
  bool crankOnLeft = true;
};

/// What a deck needs at one crank angle.
struct PumpRodSample {
  double phi = 0;      ///< crank angle (rad), 0 at the outer dead centre
  double eta = 0;      ///< stroke position (m), in [0, 2 r]
  double etaDot = 0;   ///< d eta / dt (m/s)
  double etaDDot = 0;  ///< d2 eta / dt2 (m/s^2)
  /// Inertia force of the reciprocating mass along +eta, -m eta'', as amplitudes (N) of
  /// cos(k omega t) for k = 1, 2, 4, 6 with phi = omega t (truncation O(lambda^7) m r omega^2).
  std::array<Harmonic, 4> forcing{};
};

/// Exact kinematics at crank angle phi (rad), uniform crank speed omega (rad/s), and the harmonic
/// forcing of a reciprocating mass (kg). Throws std::invalid_argument on an invalid drive.
PumpRodSample pumpRodLoad(const PumpRodDrive& d, double phi, double omega,
                          double reciprocatingMass);

/// Crank angle phi in [0, pi] (rad) at which the rod stands at eta (m): from the triangle
/// O-B-C, s = r + l - x = OC and cos phi = (s^2 + r^2 - l^2) / (2 r s). The other solution is
/// 2 pi - phi. Throws std::invalid_argument for eta outside [0, 2 r].
double crankAngleAtStroke(const PumpRodDrive& d, double eta);

/// Time-domain force (N) from cos(k omega t) amplitudes: sum c_k cos(k omega t).
double forceAt(const std::array<Harmonic, 4>& forcing, double omega, double t);

}  // namespace beamrotor::crank
