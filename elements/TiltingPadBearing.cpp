#include "elements/TiltingPadBearing.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>

#include "elements/PadFilm.hpp"

namespace beamrotor {

namespace {

constexpr double kPiPads = std::numbers::pi;
/// Films thinner than 1 % of the clearance are beyond any real surface finish (as for the
/// plain journal, FiniteJournalBearing.hpp).
constexpr double kThinnestPadFilm = 0.01;

using Complex2 = Eigen::Matrix2cd;

/// Z_k' = Z - Z t t^T Z / (t^T Z t) in pad axes (t = (0, 1)), rotated to the bearing's axes,
/// Z = K + s C for a motion e^{s Omega t} (s = i nu: whirl at nu times the spin).
Complex2 condensedPad(const PadFilmState& p, std::complex<double> s) {
  Complex2 z;
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) z(i, j) = p.stiffness[i][j] + s * p.damping[i][j];
  if (z(1, 1) == 0.0) return Complex2::Zero();  // an unloaded pad
  Complex2 reduced = z - z.col(1) * z.row(1) / z(1, 1);
  Eigen::Matrix2d q;  // columns e_k, t_k in the bearing's axes
  q << std::cos(p.pivot), -std::sin(p.pivot), std::sin(p.pivot), std::cos(p.pivot);
  return q.cast<std::complex<double>>() * reduced * q.transpose().cast<std::complex<double>>();
}

Complex2 condensedBearing(const TiltingPadPoint& point, std::complex<double> s) {
  Complex2 z = Complex2::Zero();
  for (const PadFilmState& p : point.pads) z += condensedPad(p, s);
  return z;
}

void checkGeometry(const PlainJournal& j, const TiltingPads& pads, double speed) {
  if (pads.count < 1 || !(pads.arc > 0) || !(pads.count * pads.arc < 2 * kPiPads))
    throw std::invalid_argument("the pads need a positive arc and must fit around the journal");
  if (!(pads.pivotOffset > 0 && pads.pivotOffset < 1))
    throw std::invalid_argument("a pivot lies on its pad: 0 < offset < 1");
  if (!(pads.preload >= 0 && pads.preload < 1))
    throw std::invalid_argument("the preload lies in 0 <= m < 1");
  if (!(speed > 0) || !(j.load > 0) || !(j.diameter > 0) || !(j.length > 0) ||
      !(j.clearance > 0) || !(j.viscosity > 0))
    throw std::invalid_argument("a tilting-pad bearing needs a positive speed, load and geometry");
}

}  // namespace

PadEquilibrium padEquilibrium(const TiltingPads& pads, double lengthOverDiameter,
                              const ReynoldsGrid& grid, double rho) {
  PadFilm film(pads, lengthOverDiameter, grid);
  PadEquilibrium out;
  const std::optional<double> s = film.equilibriumTilt(rho);
  if (!s) return out;
  out.loaded = true;
  out.s = *s;
  out.film = film.solve(rho, *s, true);
  return out;
}

TiltingPadPoint tiltingPadPoint(const PlainJournal& j, const TiltingPads& pads, double speed,
                                const ReynoldsGrid& grid, const TiltingPadPoint* near) {
  checkGeometry(j, pads, speed);
  const double R = j.diameter / 2, cp = j.clearance / (1 - pads.preload);
  const double forceScale = j.viscosity * speed * R * R * R * j.length / (cp * cp);
  const double load = j.load / forceScale;  // Wbar, carried along +x_b
  std::vector<double> pivots;
  for (int k = 0; k < pads.count; ++k)
    pivots.push_back(kPiPads + (pads.loadOnPad ? 0 : kPiPads / pads.count) +
                     2 * kPiPads * k / pads.count);
  std::vector<PadFilm> films(pivots.size(), PadFilm(pads, j.length / j.diameter, grid));
  std::vector<std::optional<double>> tilts(pivots.size());  // s of each pad at the current u
  // A pad the journal has left: the rho at which its tilt search last found no root. A pad
  // loads only as the journal comes nearer its pivot, so at a rho no larger it is taken as left
  // without the search (some forty films); the converged point is checked by the search.
  std::vector<std::optional<double>> leftAt(pivots.size());
  auto unit = [](double angle) { return Eigen::Vector2d(std::cos(angle), std::sin(angle)); };
  // The pads' force on the journal at u and its Jacobian (minus the static stiffness).
  struct Balance {
    Eigen::Vector2d force = Eigen::Vector2d::Zero();
    Eigen::Matrix2d stiffness = Eigen::Matrix2d::Zero();
    bool assumedLeft = false;  ///< a pad taken as left without its search
  };
  auto balance = [&](const Eigen::Vector2d& u, bool searchEveryPad) {
    Balance b;
    for (std::size_t k = 0; k < pivots.size(); ++k) {
      const Eigen::Vector2d e = unit(pivots[k]);
      const double rho = u.dot(e);
      if (!searchEveryPad && leftAt[k] && rho <= *leftAt[k]) {
        tilts[k].reset();
        b.assumedLeft = true;
        continue;
      }
      tilts[k] = films[k].equilibriumTilt(rho);
      leftAt[k].reset();
      if (!tilts[k]) leftAt[k] = rho;
      if (!tilts[k]) continue;  // a pad the journal has left carries nothing
      const FilmSolution f = films[k].solve(rho, *tilts[k], true);
      const double kr = f.stiffness[0][0] - f.stiffness[0][1] * f.stiffness[1][0] / f.stiffness[1][1];
      b.force += f.force[0] * e;
      b.stiffness += kr * e * e.transpose();
    }
    return b;
  };
  // Newton from the centre, or from `near`'s journal and tilts; a step that would close a
  // film at a pivot is shortened.
  const double thinnest = kThinnestPadFilm * (1 - pads.preload);
  Eigen::Vector2d u = Eigen::Vector2d::Zero();
  if (near && near->pads.size() == pivots.size()) {
    u = near->eccentricity * j.clearance / cp * unit(near->attitude + kPiPads);
    for (std::size_t k = 0; k < pivots.size(); ++k)
      if (near->pads[k].force != 0)
        films[k].seed(u.dot(unit(pivots[k] + kPiPads / 2)) - near->pads[k].tilt * R / cp);
      else  // a pad's tilt depends on rho alone, not on the speed: left there, left here
        leftAt[k] = u.dot(unit(pivots[k]));
  }
  Balance b = balance(u, false);
  for (int iteration = 0;; ++iteration) {
    Eigen::Vector2d residual = b.force - Eigen::Vector2d(load, 0);
    if (residual.norm() <= 1e-11 * load && b.assumedLeft) {
      b = balance(u, true);  // the pads taken as left, searched at the converged point
      residual = b.force - Eigen::Vector2d(load, 0);
    }
    if (residual.norm() <= 1e-11 * load) break;
    if (iteration == 100)
      throw std::invalid_argument("the tilting pads found no equilibrium in 100 Newton steps");
    Eigen::Vector2d step = b.stiffness.fullPivLu().solve(residual);
    double scale = 1;
    for (double pivot : pivots) {
      const double room = 1 - pads.preload - thinnest - u.dot(unit(pivot));
      const double advance = step.dot(unit(pivot));
      if (advance > 0.5 * room) scale = std::min(scale, 0.5 * room / advance);
    }
    if (scale < 1e-6)
      throw std::invalid_argument(
          "the load needs a film thinner than 1 % of the clearance at a pivot (the journal "
          "touches a pad)");
    u += scale * step;
    b = balance(u, false);
  }
  TiltingPadPoint out;
  out.speed = speed;
  out.eccentricity = u.norm() * cp / j.clearance;
  out.attitude = u.norm() > 0 ? std::remainder(std::atan2(u.y(), u.x()) - kPiPads, 2 * kPiPads) : 0;
  out.radius = j.diameter / 2;
  out.stiffnessScale = forceScale / cp;
  out.dampingScale = forceScale / (cp * speed);
  for (std::size_t k = 0; k < pivots.size(); ++k) {
    const Eigen::Vector2d e = unit(pivots[k]), t = unit(pivots[k] + kPiPads / 2);
    const double rho = u.dot(e);
    PadFilmState p;
    p.pivot = pivots[k];
    if (!tilts[k]) {  // unloaded: no force, no coefficients, the film as wide as it gets
      p.minimumFilm = (1 - pads.preload - rho) * cp / j.clearance;
      out.pads.push_back(p);
      continue;
    }
    const FilmSolution f = films[k].solve(rho, *tilts[k], true);
    p.force = f.force[0] * forceScale;
    p.tilt = (u.dot(t) - *tilts[k]) * cp / R;
    p.minimumFilm = films[k].thinnest(rho, *tilts[k]) * cp / j.clearance;
    if (p.minimumFilm < kThinnestPadFilm)
      throw std::invalid_argument("the load needs a film thinner than 1 % of the clearance on a "
                                  "pad (the journal touches it)");
    for (int r = 0; r < 2; ++r)
      for (int c = 0; c < 2; ++c) {
        p.stiffness[r][c] = f.stiffness[r][c];
        p.damping[r][c] = f.damping[r][c];
      }
    out.pads.push_back(p);
  }
  out.synchronous = tiltingPadCoefficients(out, 1);
  return out;
}

BearingCoefficients tiltingPadCoefficients(const TiltingPadPoint& point, double whirlRatio) {
  if (!(whirlRatio > 0))
    throw std::invalid_argument("tiltingPadCoefficients: the whirl ratio must be positive");
  const Complex2 z = condensedBearing(point, std::complex<double>(0, whirlRatio));
  const double ks = point.stiffnessScale, cs = point.dampingScale / whirlRatio;
  return {ks * z(0, 0).real(), ks * z(0, 1).real(), ks * z(1, 0).real(), ks * z(1, 1).real(),
          cs * z(0, 0).imag(), cs * z(0, 1).imag(), cs * z(1, 0).imag(), cs * z(1, 1).imag()};
}

BearingCoefficients tiltingPadStaticStiffness(const TiltingPadPoint& point) {
  const Complex2 z = condensedBearing(point, 0.0);
  const double ks = point.stiffnessScale;
  return {ks * z(0, 0).real(), ks * z(0, 1).real(), ks * z(1, 0).real(), ks * z(1, 1).real(),
          0, 0, 0, 0};
}

BearingCoefficients tiltingPadCoefficientsAt(const TiltingPadPoint& point,
                                              std::complex<double> lambda) {
  // A motion with no frequency of its own (a real eigenvalue) is read a hair off the real axis:
  // C is then the impedance's slope there, and K + lambda C still the impedance at lambda to
  // that hair squared.
  const double hair = 1e-9 * std::max(std::abs(lambda), point.speed);
  if (std::abs(lambda.imag()) < hair) lambda = {lambda.real(), hair};
  const Complex2 z = condensedBearing(point, lambda / point.speed);
  const double ks = point.stiffnessScale;
  std::array<double, 8> k{}, c{};
  for (int i = 0; i < 4; ++i) {
    const std::complex<double> zi = ks * z(i / 2, i % 2);
    c[i] = zi.imag() / lambda.imag();
    k[i] = zi.real() - lambda.real() * c[i];
  }
  return {k[0], k[1], k[2], k[3], c[0], c[1], c[2], c[3]};
}

}  // namespace beamrotor
