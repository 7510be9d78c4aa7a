#include "elements/Beam.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <typeinfo>

namespace beamrotor {

namespace {

/// The place of an element dof (elementDofCode) among a beam's 12 global ones.
int globalPlace(std::uint8_t code) {
  return 6 * (code >> 3) + (code & 7);
}

using Matrix4 = Eigen::Matrix4d;
using Matrix12 = Beam::Matrix12;
using Vector12 = Beam::Vector12;

/// The three-point Gauss-Legendre rule mapped to [0, 1] (points 1/2 -+ sqrt(3/5)/2, weights
/// 5/18, 8/18, 5/18): exact for polynomials of degree 5.
struct UnitGauss3 {
  std::array<double, 3> xi, w;
};
const UnitGauss3 kUnitGauss3{{0.5 - std::sqrt(0.15), 0.5, 0.5 + std::sqrt(0.15)},
                             {5.0 / 18, 8.0 / 18, 5.0 / 18}};

// Local dof positions: u v w rx ry rz at the start (0..5) and at the end (6..11).
constexpr std::array<int, 4> kPlaneXY{1, 5, 7, 11};  // v, rz: bending about local z
constexpr std::array<int, 4> kPlaneXZ{2, 4, 8, 10};  // w, ry: bending about local y
constexpr std::array<int, 2> kAxial{0, 6};
constexpr std::array<int, 2> kTorsion{3, 9};

bool isLinear(BeamTheory t) {
  return t == BeamTheory::timoshenkoLinearFullIntegration ||
         t == BeamTheory::timoshenkoLinearReducedIntegration;
}

/// Bending stiffness in one plane, dofs (v1, theta1, v2, theta2) with theta = dv/dx for a
/// shear-rigid beam. Interdependent-interpolation Timoshenko element: Przemieniecki (1968);
/// Phi = 0 gives Euler-Bernoulli.
Matrix4 hermiteStiffness(double EI, double Phi, double L) {
  Matrix4 k;
  const double L2 = L * L;
  k << 12, 6 * L, -12, 6 * L,                         //
      6 * L, (4 + Phi) * L2, -6 * L, (2 - Phi) * L2,  //
      -12, -6 * L, 12, -6 * L,                        //
      6 * L, (2 - Phi) * L2, -6 * L, (4 + Phi) * L2;
  return EI / ((1 + Phi) * L2 * L) * k;
}

/// Linear deflection and rotation; shear stiffness kGA integrated at the given Gauss points.
Matrix4 linearStiffness(double EI, double kGA, double L, bool reduced) {
  Matrix4 k = Matrix4::Zero();
  k(1, 1) = k(3, 3) = EI / L;
  k(1, 3) = k(3, 1) = -EI / L;
  const double g = 0.5 / std::sqrt(3.0);
  const std::array<double, 2> full{0.5 - g, 0.5 + g};
  const int points = reduced ? 1 : 2;
  for (int p = 0; p < points; ++p) {
    const double xi = reduced ? 0.5 : full[p];
    const double weight = L / points;
    Eigen::Vector4d B(-1 / L, -(1 - xi), 1 / L, -xi);  // shear strain v' - theta
    k += kGA * weight * B * B.transpose();
  }
  return k;
}

/// Consistent translational and rotary mass of the interdependent-interpolation element:
/// Friedman and Kosmatka, Computers & Structures 47 (1993); Phi = 0 gives the cubic Hermite
/// mass of Euler-Bernoulli.
Matrix4 hermiteMass(double rhoA, double rhoI, double Phi, double L) {
  const double P = Phi, P2 = Phi * Phi, L2 = L * L;
  Matrix4 t;
  const double a = 13.0 / 35 + 7 * P / 10 + P2 / 3, b = (11.0 / 210 + 11 * P / 120 + P2 / 24) * L,
               c = 9.0 / 70 + 3 * P / 10 + P2 / 6, d = (13.0 / 420 + 3 * P / 40 + P2 / 24) * L,
               e = (1.0 / 105 + P / 60 + P2 / 120) * L2, f = (1.0 / 140 + P / 60 + P2 / 120) * L2;
  t << a, b, c, -d,  //
      b, e, d, -f,   //
      c, d, a, -b,   //
      -d, -f, -b, e;
  Matrix4 r;
  const double g = 6.0 / 5, h = (1.0 / 10 - P / 2) * L, i = (2.0 / 15 + P / 6 + P2 / 3) * L2,
               j = (-1.0 / 30 - P / 6 + P2 / 6) * L2;
  r << g, h, -g, h,   //
      h, i, -h, j,    //
      -g, -h, g, -h,  //
      h, j, -h, i;
  const double s = (1 + P) * (1 + P);
  return rhoA * L / s * t + rhoI / (s * L) * r;
}

Matrix4 linearMass(double rhoA, double rhoI, double L) {
  Matrix4 m = Matrix4::Zero();
  for (int a : {0, 2})
    for (int b : {0, 2}) m(a, b) = rhoA * L / 6 * (a == b ? 2 : 1);
  for (int a : {1, 3})
    for (int b : {1, 3}) m(a, b) = rhoI * L / 6 * (a == b ? 2 : 1);
  return m;
}

/// Section rotation theta(xi) = N(xi) . (v1, theta1, v2, theta2) at xi = x / L in one
/// bending plane. Interdependent interpolation: Friedman and Kosmatka (1993), the shapes behind
/// hermiteMass (Phi = 0: the derivatives of the Hermite cubics); the linear elements
/// interpolate theta linearly.
Eigen::RowVector4d rotationShape(BeamTheory t, double Phi, double L, double xi) {
  if (isLinear(t)) return {0, 1 - xi, 0, xi};
  const double a = 6 * (xi * xi - xi) / L;
  return Eigen::RowVector4d(a, 3 * xi * xi - (4 + Phi) * xi + 1 + Phi, -a,
                            3 * xi * xi - (2 - Phi) * xi) /
         (1 + Phi);
}

/// Deflection v(xi) = N(xi) . (v1, theta1, v2, theta2) of the interpolation whose rotations
/// rotationShape gives: for the interdependent element v' - theta is the element's constant
/// shear strain (Friedman and Kosmatka 1993), Phi = 0 gives the Hermite cubics; the linear
/// elements interpolate v linearly.
Eigen::RowVector4d deflectionShape(BeamTheory t, double Phi, double L, double xi) {
  if (isLinear(t)) return {1 - xi, 0, xi, 0};
  const double x2 = xi * xi, x3 = x2 * xi;
  return Eigen::RowVector4d(1 - 3 * x2 + 2 * x3 + Phi * (1 - xi),
                            L * (xi - 2 * x2 + x3 + Phi * (xi - x2) / 2),
                            3 * x2 - 2 * x3 + Phi * xi, L * (x3 - x2 - Phi * (xi - x2) / 2)) /
         (1 + Phi);
}

/// Slope dv/dx at xi = x / L of the deflection interpolation deflectionShape (its derivative):
/// the total slope, bending rotation plus shear strain, through which an axial force acts.
Eigen::RowVector4d slopeShape(BeamTheory t, double Phi, double L, double xi) {
  if (isLinear(t)) return {-1 / L, 0, 1 / L, 0};
  const double x2 = xi * xi;
  return Eigen::RowVector4d(6 * x2 - 6 * xi - Phi, L * (1 - 4 * xi + 3 * x2 + Phi * (1 - 2 * xi) / 2),
                            6 * xi - 6 * x2 + Phi, L * (3 * x2 - 2 * xi - Phi * (1 - 2 * xi) / 2)) /
         (L * (1 + Phi));
}

/// int_0^L N(x) v'^T v' dx in one bending plane for N linear from N0 to N1; the integrand is
/// at most of degree 5, which 3 Gauss points integrate exactly.
Matrix4 geometricBending(BeamTheory t, double Phi, double L, double N0, double N1) {
  const auto& [xi, w] = kUnitGauss3;
  Matrix4 k = Matrix4::Zero();
  for (int p = 0; p < 3; ++p) {
    const Eigen::RowVector4d B = slopeShape(t, Phi, L, xi[p]);
    k += w[p] * L * (N0 + (N1 - N0) * xi[p]) * B.transpose() * B;
  }
  return k;
}

/// Deflection and section rotation at x of an element clamped at both ends under a uniform
/// load q per length in one bending plane (EI, shear parameter Phi = 12 EI / (kappa G A L^2)).
/// From the Timoshenko beam equations EI theta'' + kappa G A (v' - theta) = 0 and
/// kappa G A (v'' - theta') + q = 0 with v = theta = 0 at both ends:
///   theta = q x (L - x) (L - 2x) / (12 EI),
///   v = q x^2 (L - x)^2 / (24 EI) + q x (L - x) / (2 kappa G A),
/// the shear term being Phi L^2 q x (L - x) / (24 EI); Phi = 0 gives Euler-Bernoulli. Its end
/// forces are the fixed-end loads of localLoad(), so added to the end-loaded shapes it makes
/// the field exact between the nodes.
struct SpanBending {
  double deflection, rotation;
};
SpanBending clampedSpanBending(double q, double EI, double Phi, double L, double x) {
  const double a = x * (L - x);
  return {q * a * (a + Phi * L * L) / (24 * EI), q * a * (L - 2 * x) / (12 * EI)};
}

/// The same for the antisymmetric load d (2 x / L - 1) (the linear part of a trapezoidal
/// load; d is half the rise from start to end). With s = x / L and a = s (1 - s), solving the
/// same equations:
///   v = d L^4 a (2s - 1) (3 (1 + Phi) a + 5 Phi^2 + 6 Phi) / (360 EI (1 + Phi)),
///   theta = d L^3 a (5 (1 + Phi) a - 1) / (60 EI (1 + Phi));
/// Phi = 0 gives the Euler-Bernoulli v = d L^4 a^2 (2s - 1) / (120 EI).
SpanBending clampedAntisymmetricBending(double d, double EI, double Phi, double L, double x) {
  const double s = x / L, a = s * (1 - s), L3 = L * L * L;
  return {d * L3 * L * a * (2 * s - 1) * (3 * (1 + Phi) * a + 5 * Phi * Phi + 6 * Phi) /
              (360 * EI * (1 + Phi)),
          d * L3 * a * (5 * (1 + Phi) * a - 1) / (60 * EI * (1 + Phi))};
}

/// Fixed-end forces of a clamped-clamped element under a linear transverse load of mean m and
/// half rise d in one bending plane: the end forces along the load (start, end) and the end
/// moments (start, end) about the plane's normal, positive counter-clockwise seen from its
/// +normal, as the element's consistent load vector (which for the exact shape functions of
/// the Euler-Bernoulli and interdependent Timoshenko elements equals the fixed-end forces;
/// Phi = 0 gives L (7 qa + 3 qb) / 20 and L^2 (3 qa + 2 qb) / 60 at the start).
struct FixedEnd {
  double forceStart, forceEnd, momentStart, momentEnd;
};
FixedEnd fixedEndForces(double m, double d, double Phi, double L) {
  const double shearShare = d * L * (5 * Phi + 6) / (30 * (1 + Phi));
  const double antisymmetricMoment = d * L * L / (60 * (1 + Phi));
  return {m * L / 2 - shearShare, m * L / 2 + shearShare,
          m * L * L / 12 - antisymmetricMoment, -m * L * L / 12 - antisymmetricMoment};
}

/// Bending about local y uses theta = -ry = dw/dx: flip the rotation signs.
Matrix4 flipRotations(const Matrix4& m) {
  const Eigen::Vector4d s(1, -1, 1, -1);
  return s.asDiagonal() * m * s.asDiagonal();
}

template <std::size_t N, class M>
void place(Matrix12& K, const std::array<int, N>& at, const M& block) {
  for (std::size_t a = 0; a < N; ++a)
    for (std::size_t b = 0; b < N; ++b) K(at[a], at[b]) += block(a, b);
}

Eigen::Matrix2d twoNode(double k) {
  Eigen::Matrix2d m;
  m << k, -k, -k, k;
  return m;
}

Eigen::Matrix2d twoNodeMass(double m, bool lumped) {
  Eigen::Matrix2d r;
  if (lumped)
    r << m / 2, 0, 0, m / 2;
  else
    r << m / 3, m / 6, m / 6, m / 3;
  return r;
}

/// T^T A T with T = diag(R, R, R, R), done block by block.
Matrix12 toGlobal(const Matrix12& A, const Eigen::Matrix3d& R) {
  // A beam along global x with the default z (every planar line model) needs no rotation:
  // skipping it halves the cost of assembling such models (measured on the bench).
  if (R == Eigen::Matrix3d::Identity()) return A;
  Matrix12 G;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      G.block<3, 3>(3 * i, 3 * j) = R.transpose() * A.block<3, 3>(3 * i, 3 * j) * R;
  return G;
}

}  // namespace

Beam::Beam(int n1, const Eigen::Vector3d& x1, int n2, const Eigen::Vector3d& x2,
           std::shared_ptr<const Section> section, DofSet carried, BeamOptions options,
           const Eigen::Vector3d& zHint)
    : Beam(n1, n2, x2 - x1, (x2 - x1).norm(), std::move(section), carried, options, zHint) {}

Beam::Beam(int n1, int n2, const Eigen::Vector3d& direction, double length,
           std::shared_ptr<const Section> section, DofSet carried, BeamOptions options,
           const Eigen::Vector3d& zHint)
    : nodes_{n1, n2} {
  Properties p;
  p.section = std::move(section);
  p.carried = carried;
  p.options = options;
  p.L = length;
  const double directionNorm = direction.norm();
  if (!(p.L > 0) || !(directionNorm > 0))
    throw std::invalid_argument("beam element of zero length");
  if (!p.section) throw std::invalid_argument("beam element without a section");
  const Eigen::Vector3d ex = direction / directionNorm;
  Eigen::Vector3d hint = zHint;
  if (std::abs(ex.dot(hint.normalized())) > 1 - 1e-9) hint = Eigen::Vector3d::UnitY();
  const Eigen::Vector3d ez = (hint - hint.dot(ex) * ex).normalized();
  const Eigen::Vector3d ey = ez.cross(ex);
  p.R.row(0) = ex;
  p.R.row(1) = ey;
  p.R.row(2) = ez;
  // The carried dofs must not couple to the dropped ones.
  if (carried == DofSet::planar() && (std::abs(ex.z()) > 1e-12 || ez.z() < 1 - 1e-12))
    throw std::invalid_argument("a planar beam must lie in the x-y plane");
  if ((carried == DofSet::lateral() || carried == DofSet::torsion()) && ex.x() < 1 - 1e-12)
    throw std::invalid_argument("a rotor shaft element must lie along the x axis");
  setProperties(std::move(p));
}

void Beam::Properties::numberDofs() {
  count = 0;
  for (int end = 0; end < 2; ++end)
    for (Dof d : kAllDofs) {
      if (!carried.contains(d)) continue;
      // A released rotation whose local axis is a global axis is not touched at all, so a
      // node where every element is hinged about it does not get that dof.
      bool dropped = false;
      for (int r : released) {
        const int axis = r % 6 - 3;
        if (r / 6 == end && isRotation(d) && std::abs(R(axis, dofIndex(d) - 3)) > 1 - 1e-12)
          dropped = true;
      }
      if (!dropped) dofCodes[count++] = elementDofCode(end, d);
    }
}

void Beam::setProperties(Properties p) {
  p.numberDofs();
  thread_local std::weak_ptr<const Properties> lastMade;
  if (std::shared_ptr<const Properties> last = lastMade.lock(); last && *last == p) {
    p_ = std::move(last);
    return;
  }
  p_ = std::make_shared<const Properties>(std::move(p));
  lastMade = p_;
}

void Beam::release(int end, Dof rotation) {
  if ((end != 0 && end != 1) || !isRotation(rotation))
    throw std::invalid_argument("a beam end release needs end 0 or 1 and a rotation rx, ry, rz");
  const int local = 6 * end + dofIndex(rotation);
  Properties p = *p_;
  if (std::find(p.released.begin(), p.released.end(), local) == p.released.end())
    p.released.push_back(local);
  setProperties(std::move(p));
}

void Beam::setSlack(bool slack) {
  Properties p = *p_;
  p.slack = slack;
  setProperties(std::move(p));
}

void Beam::setDistributedLoad(const Eigen::Vector3d& q) {
  setDistributedLoad(q, q);
}

void Beam::setDistributedLoad(const Eigen::Vector3d& qStart, const Eigen::Vector3d& qEnd) {
  Properties p = *p_;
  const ElementSpanLoad q = spanLoadOf(qStart, qEnd);
  p.qMean = q.mean;
  p.qHalfRise = q.halfRise;
  setProperties(std::move(p));
}

void Beam::setImposedStrain(const Eigen::Vector3d& strain) {
  Properties p = *p_;
  p.strain = strain;
  setProperties(std::move(p));
}

ElementSpanLoad Beam::spanLoadOf(const Eigen::Vector3d& qStart, const Eigen::Vector3d& qEnd) const {
  return {p_->R * (qStart + qEnd) / 2, p_->R * (qEnd - qStart) / 2, Eigen::Vector3d::Zero()};
}

void Beam::setAxialPreload(double N) {
  Properties p = *p_;
  p.axialPreload = N;
  setProperties(std::move(p));
}

std::string Beam::kind() const {
  switch (p_->options.theory) {
    case BeamTheory::eulerBernoulli:
      return "beam-eb";
    case BeamTheory::timoshenko:
      return "beam-timoshenko";
    case BeamTheory::timoshenkoLinearFullIntegration:
      return "beam-timoshenko-linear-full";
    case BeamTheory::timoshenkoLinearReducedIntegration:
      return "beam-timoshenko-linear-reduced";
  }
  return "beam";
}

std::array<double, 2> Beam::shearParameters() const {
  if (p_->options.theory != BeamTheory::timoshenko) return {0, 0};
  const Section& s = *p_->section;
  const double GAL2 = s.material.G * s.A * p_->L * p_->L;
  return {s.kappaY > 0 ? 12 * s.EIz() / (s.kappaY * GAL2) : 0,
          s.kappaZ > 0 ? 12 * s.EIy() / (s.kappaZ * GAL2) : 0};
}

Matrix12 Beam::localStiffness() const {
  const Section& s = *p_->section;
  const double L = p_->L, G = s.material.G;
  Matrix12 K = Matrix12::Zero();
  place(K, kAxial, twoNode(s.EA() / L));
  place(K, kTorsion, twoNode(s.GJ() / L));
  const BeamTheory t = p_->options.theory;
  if (isLinear(t)) {
    const bool reduced = t == BeamTheory::timoshenkoLinearReducedIntegration;
    if (s.kappaY <= 0 || s.kappaZ <= 0)
      throw std::invalid_argument("the linear Timoshenko element needs shear coefficients");
    place(K, kPlaneXY, linearStiffness(s.EIz(), s.kappaY * G * s.A, L, reduced));
    place(K, kPlaneXZ, flipRotations(linearStiffness(s.EIy(), s.kappaZ * G * s.A, L, reduced)));
  } else {
    const auto [phiY, phiZ] = shearParameters();
    place(K, kPlaneXY, hermiteStiffness(s.EIz(), phiY, L));
    place(K, kPlaneXZ, flipRotations(hermiteStiffness(s.EIy(), phiZ, L)));
  }
  return K;
}

Matrix12 Beam::localMass() const {
  const Section& s = *p_->section;
  const double L = p_->L, rho = s.material.rho, rhoA = s.rhoA();
  const bool lumped = p_->options.mass == MassModel::lumped;
  const double rhoIz = p_->options.rotaryInertia ? rho * s.Iz : 0;
  const double rhoIy = p_->options.rotaryInertia ? rho * s.Iy : 0;
  Matrix12 M = Matrix12::Zero();
  place(M, kAxial, twoNodeMass(rhoA * L, lumped));
  place(M, kTorsion, twoNodeMass(rho * s.Ip() * L, lumped));
  if (lumped) {
    for (int i : {1, 2, 7, 8}) M(i, i) = rhoA * L / 2;
    for (int i : {5, 11}) M(i, i) = rhoIz * L / 2;
    for (int i : {4, 10}) M(i, i) = rhoIy * L / 2;
    return M;
  }
  const BeamTheory t = p_->options.theory;
  if (isLinear(t)) {
    place(M, kPlaneXY, linearMass(rhoA, rhoIz, L));
    place(M, kPlaneXZ, linearMass(rhoA, rhoIy, L));
  } else {
    const auto [phiY, phiZ] = shearParameters();
    place(M, kPlaneXY, hermiteMass(rhoA, rhoIz, phiY, L));
    place(M, kPlaneXZ, flipRotations(hermiteMass(rhoA, rhoIy, phiZ, L)));
  }
  return M;
}

Matrix12 Beam::localGeometricStiffness(double N0, double N1) const {
  const Section& s = *p_->section;
  const BeamTheory t = p_->options.theory;
  const auto [phiY, phiZ] = shearParameters();
  Matrix12 KG = Matrix12::Zero();
  place(KG, kPlaneXY, geometricBending(t, phiY, p_->L, N0, N1));
  place(KG, kPlaneXZ, flipRotations(geometricBending(t, phiZ, p_->L, N0, N1)));
  // Twist is interpolated linearly: int N (Ip/A) / L^2 dx = mean N (Ip/A) / L.
  if (s.A > 0) place(KG, kTorsion, twoNode((N0 + N1) / 2 * s.Ip() / (s.A * p_->L)));
  return KG;
}

ElementMatrix Beam::geometricStiffness(const ElementVector& u) const {
  if (p_->slack) return ElementMatrix::Zero(p_->count, p_->count);
  const SectionForceSeries f = sectionForceSeries(u);
  Matrix12 KG = localGeometricStiffness(f.at(0).N + p_->axialPreload, f.at(1).N + p_->axialPreload);
  if (!p_->released.empty()) {
    // Released rotations follow the kept dofs as in the mass matrix: KG -> T^T KG T.
    Matrix12 K = localStiffness();
    condense(K, &KG, nullptr);
  }
  return toCarried(toGlobal(KG, p_->R));
}

Vector12 Beam::localLoad(const ElementSpanLoad& q) const {
  const double L = p_->L;
  const Eigen::Vector3d &m = q.mean, &d = q.halfRise;
  Vector12 f = Vector12::Zero();
  // Linear shape functions (the bar, and the linear elements' deflections): L (2 qa + qb) / 6
  // at the start, L (qa + 2 qb) / 6 at the end.
  for (int k = 0; k < 3; ++k) {
    f[k] = m[k] * L / 2 - d[k] * L / 6;
    f[6 + k] = m[k] * L / 2 + d[k] * L / 6;
  }
  if (!isLinear(p_->options.theory)) {
    // Bending in x-y (moments about z) and in x-z (about y, where theta = -ry flips the
    // moments' signs). A uniform load's moments q L^2 / 12 are the same for both theories.
    const auto [phiY, phiZ] = shearParameters();
    const FixedEnd y = fixedEndForces(m.y(), d.y(), phiY, L);
    const FixedEnd z = fixedEndForces(m.z(), d.z(), phiZ, L);
    f[1] = y.forceStart, f[7] = y.forceEnd, f[5] = y.momentStart, f[11] = y.momentEnd;
    f[2] = z.forceStart, f[8] = z.forceEnd, f[4] = -z.momentStart, f[10] = -z.momentEnd;
  }
  // An imposed strain: held at both ends the element stays straight and unmoved (the clamped
  // solution is u = v = w = 0 for every theory), so its section carries N = -EA e, My = -EIy ky,
  // Mz = -EIz kz along its whole length, no shear; the forces holding its ends are those
  // resultants on its end faces, and the equivalent nodal loads their negatives.
  const Section& sec = *p_->section;
  const Eigen::Vector3d held(-sec.EA() * q.strain[0], -sec.EIy() * q.strain[1],
                             -sec.EIz() * q.strain[2]);
  for (int k = 0; k < 3; ++k) {
    const int at = k == 0 ? 0 : 3 + k;  // u, ry, rz
    f[at] += held[k];
    f[6 + at] -= held[k];
  }
  return f;
}

void Beam::condense(Matrix12& K, Matrix12* M, Vector12* f) const {
  if (p_->released.empty()) return;
  // Kept dofs a, released dofs b: u_b = Kbb^-1 (f_b - Kba u_a), so with T = [I; -Kbb^-1 Kba]
  // the condensed matrices are T^T K T (= Kaa - Kab Kbb^-1 Kba), T^T M T and T^T f.
  const int nb = int(p_->released.size());
  Eigen::MatrixXd Kbb(nb, nb), Kba(nb, 12);
  for (int i = 0; i < nb; ++i) {
    Kba.row(i) = K.row(p_->released[i]);
    for (int j = 0; j < nb; ++j) Kbb(i, j) = K(p_->released[i], p_->released[j]);
  }
  Eigen::MatrixXd X = Kbb.ldlt().solve(Kba);  // Kbb^-1 Kba (released columns give identity)
  Matrix12 T = Matrix12::Identity();
  for (int i = 0; i < nb; ++i) T.row(p_->released[i]) = -X.row(i);
  for (int i = 0; i < nb; ++i) T(p_->released[i], p_->released[i]) = 0;
  // Rows of T for released dofs express them through the kept ones; their own columns vanish.
  for (int i = 0; i < nb; ++i) T.col(p_->released[i]).setZero();
  const Eigen::VectorXd before = K.diagonal().cwiseAbs();
  K = T.transpose() * K * T;
  // Kaa - Kab Kbb^-1 Kba cancels exactly where the releases leave no stiffness (a bar hinged
  // at both ends has none in bending), but in floating point leaves round-off there, which a
  // solver scaled by diag(K) would take for real stiffness: what is below round-off of the
  // unreleased entries is zero.
  for (int i = 0; i < 12; ++i)
    for (int j = 0; j < 12; ++j)
      if (std::abs(K(i, j)) <= 1e-12 * std::sqrt(before[i] * before[j])) K(i, j) = 0;
  if (M) *M = T.transpose() * (*M) * T;
  if (f) *f = T.transpose() * (*f);
}

ElementMatrix Beam::toCarried(const Matrix12& global) const {
  const int n = p_->count;
  std::array<int, 12> at{};  // each kept dof's place among the 12 global ones
  for (int a = 0; a < n; ++a) at[a] = globalPlace(p_->dofCodes[a]);
  ElementMatrix out(n, n);
  for (int a = 0; a < n; ++a)
    for (int b = 0; b < n; ++b) out(a, b) = global(at[a], at[b]);
  return out;
}

ElementMatrix Beam::stiffness() const {
  if (p_->slack) return ElementMatrix::Zero(p_->count, p_->count);
  Matrix12 K = localStiffness();
  condense(K, nullptr, nullptr);
  return toCarried(toGlobal(K, p_->R));
}

ElementMatrix Beam::mass() const {
  Matrix12 M = localMass();
  if (!p_->released.empty()) {
    Matrix12 K = localStiffness();
    condense(K, &M, nullptr);
  }
  return toCarried(toGlobal(M, p_->R));
}

Matrix12 Beam::localGyroscopic() const {
  // A cross-section spinning at Omega about its tilted normal carries the angular momentum
  // rho Ip Omega per length; its rate under tilt rates gives moments coupling the section
  // rotations ry, rz (Nelson and McVaugh 1976; with shear, Nelson 1980):
  //   G = rho Ip int (Ny^T Nz - Nz^T Ny) dx,
  // Ny, Nz interpolating ry and rz from the element dofs. Sign: for a rigid body this is
  // Jp [0 1; -1 0] on (ry, rz), which makes forward whirl stiffen with speed.
  Matrix12 G = Matrix12::Zero();
  if (!p_->options.rotaryInertia) return G;
  const Section& s = *p_->section;
  const double rhoIp = s.material.rho * s.Ip(), L = p_->L;
  if (p_->options.mass == MassModel::lumped) {
    for (int end : {0, 6}) {
      G(end + 4, end + 5) = rhoIp * L / 2;
      G(end + 5, end + 4) = -rhoIp * L / 2;
    }
    return G;
  }
  const BeamTheory t = p_->options.theory;
  const auto [phiY, phiZ] = shearParameters();
  // rz = Nz (v1, rz1, v2, rz2); the x-z plane interpolates theta = -ry from (w1, -ry1, w2,
  // -ry2), so ry = -N (w1, -ry1, w2, -ry2). Rotation shapes are quadratic: 3 Gauss points
  // integrate the products exactly.
  const Eigen::Vector4d flip(1, -1, 1, -1);
  const auto& [xi, w] = kUnitGauss3;
  Matrix4 B = Matrix4::Zero();  // int Ny^T Nz dx: rows (w1, ry1, w2, ry2), cols (v1, rz1, v2, rz2)
  for (int p = 0; p < 3; ++p) {
    const Eigen::RowVector4d Nz = rotationShape(t, phiY, L, xi[p]);
    const Eigen::RowVector4d Ny = -rotationShape(t, phiZ, L, xi[p]) * flip.asDiagonal();
    B += w[p] * L * Ny.transpose() * Nz;
  }
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b) {
      G(kPlaneXZ[a], kPlaneXY[b]) += rhoIp * B(a, b);
      G(kPlaneXY[b], kPlaneXZ[a]) -= rhoIp * B(a, b);
    }
  return G;
}

ElementMatrix Beam::gyroscopic() const {
  if (!p_->options.rotaryInertia || !p_->carried.contains(Dof::ry) ||
      !p_->carried.contains(Dof::rz))
    return {};
  Matrix12 G = localGyroscopic();
  if (!p_->released.empty()) {
    // Released rotations follow the kept dofs as in the mass matrix: G -> T^T G T.
    Matrix12 K = localStiffness();
    condense(K, &G, nullptr);
  }
  return toCarried(toGlobal(G, p_->R));
}

ElementVector Beam::loadOf(const ElementSpanLoad& q) const {
  if (q.isZero() || p_->slack) return {};
  Vector12 f = localLoad(q);
  if (!p_->released.empty()) {
    Matrix12 K = localStiffness();
    condense(K, nullptr, &f);
  }
  Vector12 g;
  for (int i = 0; i < 4; ++i) g.segment<3>(3 * i) = p_->R.transpose() * f.segment<3>(3 * i);
  ElementVector out(p_->count);
  for (int a = 0; a < p_->count; ++a) out[a] = g[globalPlace(p_->dofCodes[a])];
  return out;
}

Vector12 Beam::toLocal(const ElementVector& u) const {
  Vector12 g = Vector12::Zero();
  for (int a = 0; a < p_->count; ++a) g[globalPlace(p_->dofCodes[a])] = u[a];
  Vector12 l;
  for (int i = 0; i < 4; ++i) l.segment<3>(3 * i) = p_->R * g.segment<3>(3 * i);
  return l;
}

Vector12 Beam::localEndDisplacements(const ElementVector& u, const ElementSpanLoad& q) const {
  Vector12 l = toLocal(u);
  if (p_->released.empty()) return l;
  const Matrix12 K = localStiffness();
  const Vector12 f = q.isZero() ? Vector12::Zero() : localLoad(q);
  for (int b : p_->released) l[b] = 0;  // a node may carry the axis: its value is not the end's
  const int nb = int(p_->released.size());
  Eigen::MatrixXd Kbb(nb, nb);
  Eigen::VectorXd rhs(nb);
  for (int i = 0; i < nb; ++i) {
    rhs[i] = f[p_->released[i]] - K.row(p_->released[i]).dot(l);
    for (int j = 0; j < nb; ++j) Kbb(i, j) = K(p_->released[i], p_->released[j]);
  }
  const Eigen::VectorXd lb = Kbb.ldlt().solve(rhs);
  for (int i = 0; i < nb; ++i) l[p_->released[i]] = lb[i];
  return l;
}

bool Beam::releases(int end) const {
  return std::any_of(p_->released.begin(), p_->released.end(), [&](int r) { return r / 6 == end; });
}

std::array<double, kDofKinds> Beam::displacementAt(const ElementVector& u, double s,
                                                   const ElementSpanLoad& q) const {
  // 1. End values in the element frame; bending about local z interpolates (v, rz), about
  //    local y (w, -ry) (right-hand rule: dw/dx = -ry).
  const Vector12 l = localEndDisplacements(u, q);
  const BeamTheory t = p_->options.theory;
  const auto [phiY, phiZ] = shearParameters();
  const Eigen::Vector4d xy(l[1], l[5], l[7], l[11]), xz(l[2], -l[4], l[8], -l[10]);
  Eigen::Vector3d d((1 - s) * l[0] + s * l[6], (deflectionShape(t, phiY, p_->L, s) * xy).value(),
                    (deflectionShape(t, phiZ, p_->L, s) * xz).value());
  Eigen::Vector3d r((1 - s) * l[3] + s * l[9], -(rotationShape(t, phiZ, p_->L, s) * xz).value(),
                    (rotationShape(t, phiY, p_->L, s) * xy).value());

  // 2. The span load's share: a bar fixed at both ends (EA u'' + qx = 0) and, for the elements
  //    with fixed-end moments, the clamped-clamped bending solution.
  if (!q.isZero()) {
    const Section& sec = *p_->section;
    const double x = s * p_->L, a = s * (1 - s);
    // EA u'' + qx = 0 with u = 0 at both ends: the mean's parabola and the rise's cubic.
    d.x() += (q.mean.x() * a / 2 + q.halfRise.x() * a * (2 * s - 1) / 6) * p_->L * p_->L /
             sec.EA();
    if (!isLinear(t)) {
      const auto bending = [&](int k, double EI, double Phi) {
        const SpanBending mean = clampedSpanBending(q.mean[k], EI, Phi, p_->L, x);
        const SpanBending rise = clampedAntisymmetricBending(q.halfRise[k], EI, Phi, p_->L, x);
        return SpanBending{mean.deflection + rise.deflection, mean.rotation + rise.rotation};
      };
      const SpanBending y = bending(1, sec.EIz(), phiY);
      const SpanBending z = bending(2, sec.EIy(), phiZ);
      d.y() += y.deflection;
      r.z() += y.rotation;
      d.z() += z.deflection;
      r.y() -= z.rotation;
    }
  }

  // 3. Back to the global frame.
  const Eigen::Vector3d dg = p_->R.transpose() * d, rg = p_->R.transpose() * r;
  return {dg.x(), dg.y(), dg.z(), rg.x(), rg.y(), rg.z()};
}

SectionForceSeries Beam::sectionForceSeries(const ElementVector& u,
                                            const ElementSpanLoad& q) const {
  if (p_->slack) return {};
  // Forces the nodes exert on the element (local frame): K l - f with the released rotations
  // recovered, which vanishes on their rows; then equilibrium of the part [0, x = s L].
  // With q(s) = qa + (qb - qa) s: the load on [0, x] is qa L s + (qb - qa) L s^2 / 2 and its
  // moment about the cut qa L^2 s^2 / 2 + (qb - qa) L^2 s^3 / 6.
  const Vector12 F = localStiffness() * localEndDisplacements(u, q) - localLoad(q);
  const Eigen::Vector3d qa = q.mean - q.halfRise, rise = 2 * q.halfRise;
  const double L = p_->L;
  SectionForceSeries r;
  r.c[0] = {-F[0], -F[1], -F[2], -F[3], -F[4], -F[5]};
  r.c[1] = {-qa.x() * L, -qa.y() * L, -qa.z() * L, 0, -L * F[2], L * F[1]};
  r.c[2] = {-rise.x() * L / 2, -rise.y() * L / 2, -rise.z() * L / 2, 0, -qa.z() * L * L / 2,
            qa.y() * L * L / 2};
  r.c[3] = {0, 0, 0, 0, -rise.z() * L * L / 6, rise.y() * L * L / 6};
  return r;
}

bool Beam::sameMatricesAs(const Element& other) const {
  if (typeid(other) != typeid(Beam)) return false;
  const Beam& b = static_cast<const Beam&>(other);
  return p_ == b.p_ || *p_ == *b.p_;
}

}  // namespace beamrotor
