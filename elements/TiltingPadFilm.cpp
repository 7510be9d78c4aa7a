#include "elements/TiltingPadFilm.hpp"

#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include "elements/TurnedBearing.hpp"

namespace beamrotor {

namespace {

bool loadedAt(const TiltingPadPoint& p, int pad) {
  return pad >= 0 && pad < int(p.pads.size()) && p.pads[std::size_t(pad)].stiffness[1][1] != 0;
}

}  // namespace

bool padEverLoaded(const std::vector<TiltingPadPoint>& points, int pad) {
  for (const TiltingPadPoint& p : points)
    if (loadedAt(p, pad)) return true;
  return false;
}

TiltingPadFilm::TiltingPadFilm(int journal, int padNode,
                               std::shared_ptr<const std::vector<TiltingPadPoint>> points, int pad,
                               double loadAngle, double inertia)
    : journal_(journal),
      padNode_(padNode),
      points_(std::move(points)),
      pad_(pad),
      loadAngle_(loadAngle),
      inertia_(inertia) {
  if (!points_ || points_->empty())
    throw std::invalid_argument("tilting-pad film: no operating points");
  if (!(inertia >= 0)) throw std::invalid_argument("tilting-pad film: the pad's inertia is >= 0");
  for (const TiltingPadPoint& p : *points_) speeds_.push_back(p.speed);
  // Each point's nearest point (in the table's order) where the pad carries a film.
  const int n = int(points_->size());
  for (int i = 0; i < n; ++i) {
    int best = -1;
    for (int j = 0; j < n; ++j)
      if (loadedAt((*points_)[std::size_t(j)], pad) &&
          (best < 0 || std::abs(j - i) < std::abs(best - i)))
        best = j;
    nearestLoaded_.push_back(best < 0 ? std::nullopt : std::optional<std::size_t>(best));
  }
}

ElementDofs TiltingPadFilm::dofs() const {
  static constexpr std::uint8_t codes[] = {elementDofCode(0, Dof::uy), elementDofCode(0, Dof::uz),
                                           elementDofCode(1, Dof::rx)};
  return {{journal_, padNode_}, codes, 3};
}

ElementMatrix TiltingPadFilm::filmAt(std::size_t i, bool damping) const {
  if (nearestLoaded_[i] != i) {
    // The journal has left the pad: no film couples it. Its tilt keeps the nearest loaded
    // point's own stiffness or damping alone, so that the equations stay regular (a
    // relaxation of the pad's own, apart from the rotor); nothing for a pad never loaded.
    ElementMatrix out = ElementMatrix::Zero(3, 3);
    if (nearestLoaded_[i]) out(2, 2) = filmAt(*nearestLoaded_[i], damping)(2, 2);
    return out;
  }
  const TiltingPadPoint& point = (*points_)[i];
  const PadFilmState& p = point.pads[std::size_t(pad_)];
  const double radius = point.radius;
  // Q: e_k, t_k in the bearing's axes (x_b -> y, y_b -> z), turned by the load angle.
  const double a = p.pivot + loadAngle_;
  Eigen::Matrix<double, 3, 2> b;
  b << std::cos(a), -std::sin(a), std::sin(a), std::cos(a), 0, -radius;
  Eigen::Matrix2d z;
  const auto& m = damping ? p.damping : p.stiffness;
  z << m[0][0], m[0][1], m[1][0], m[1][1];
  z *= damping ? point.dampingScale : point.stiffnessScale;
  return b * z * b.transpose();
}

ElementMatrix TiltingPadFilm::interpolated(double speed, bool damping) const {
  const TableBracket s = tableBracket(speeds_, speed);
  ElementMatrix out = filmAt(s.low, damping);
  if (s.t != 0) out = (1 - s.t) * out + s.t * filmAt(s.low + 1, damping);
  return out;
}

ElementMatrix TiltingPadFilm::stiffnessAt(double speed) const { return interpolated(speed, false); }

ElementMatrix TiltingPadFilm::dampingAt(double speed) const { return interpolated(speed, true); }

ElementMatrix TiltingPadFilm::mass() const {
  if (inertia_ == 0) return {};
  ElementMatrix m = ElementMatrix::Zero(3, 3);
  m(2, 2) = inertia_;
  return m;
}

BearingCoefficients TiltingPadFilm::synchronousAt(double speed) const {
  // The massless pad condensed at whirl = spin: K + i Omega C over (uy, uz, delta), delta
  // eliminated (the same Z_k' as tiltingPadCoefficients, pad by pad).
  const ElementMatrix k = stiffnessAt(speed), c = dampingAt(speed);
  const double omega = speed > 0 ? speed : speeds_.front();
  Eigen::Matrix3cd z = k.cast<std::complex<double>>() +
                       std::complex<double>(0, omega) * c.cast<std::complex<double>>();
  const Eigen::Matrix2cd r = z.topLeftCorner<2, 2>() -
                             z.topRightCorner<2, 1>() * z.bottomLeftCorner<1, 2>() / z(2, 2);
  return {r(0, 0).real(), r(0, 1).real(), r(1, 0).real(), r(1, 1).real(),
          r(0, 0).imag() / omega, r(0, 1).imag() / omega, r(1, 0).imag() / omega,
          r(1, 1).imag() / omega};
}

}  // namespace beamrotor
