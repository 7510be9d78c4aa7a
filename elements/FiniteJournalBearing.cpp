#include "elements/FiniteJournalBearing.hpp"

#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "fem/rotor/SpeedRoot.hpp"

namespace beamrotor {

namespace {

constexpr double kPiFilm = std::numbers::pi;

std::string filmRatioText(double v) {
  std::string s = std::to_string(v);
  while (s.size() > 1 && s.back() == '0') s.pop_back();
  return s;
}

/// The full circle's film at eps (the film starts at its largest gap, theta = 0), with the
/// stiffness across the line of centres from the turned film (see the header).
FilmSolution filmAt(double eps, double lengthOverDiameter, const ReynoldsGrid& grid,
                    const JournalMotion& motion, bool withCoefficients,
                    std::vector<char>* cavity = nullptr) {
  if (!(eps > 0 && eps < 1) || !(lengthOverDiameter > 0) || grid.circumferential < 8 ||
      grid.axial < 1)
    throw std::invalid_argument(
        "solveFilm: needs 0 < eps < 1, L/D > 0 and a grid of at least 8 x 1");
  FilmArc circle;
  circle.a = eps;
  FilmSolution out =
      solveArcFilm(circle, lengthOverDiameter, grid, motion, withCoefficients, cavity);
  if (!withCoefficients) return out;
  // A plain bearing has no preferred direction: the film starts at the largest gap wherever
  // the journal is, so a displacement across the line of centres (axis 2, eta) turns the
  // whole film by -eta / eps, F(eta) = R(-eta / eps) F. Its stiffness is exact from the force:
  // -dF/deta = (-F2, F1) / eps (Lund's derivation from the static solution). Along the line of
  // centres (axis 1) the largest gap stays at theta = 0 and the linearised film above holds.
  out.stiffness[0][1] = -out.force[1] / eps;
  out.stiffness[1][1] = out.force[0] / eps;
  return out;
}

}  // namespace

FilmSolution solveFilm(double eps, double lengthOverDiameter, const ReynoldsGrid& grid,
                       const JournalMotion& motion) {
  return filmAt(eps, lengthOverDiameter, grid, motion, true);
}

JournalOperatingPoint finiteJournalPoint(const PlainJournal& bearing, double speed,
                                         const ReynoldsGrid& grid) {
  const double ld = bearing.length / bearing.diameter;
  const double target = ld * ld / bearing.sommerfeld(speed);  // |Fbar| = 1 / (pi S)
  if (!(target > 0) || !std::isfinite(target))
    throw std::invalid_argument(
        "a plain journal bearing needs a positive speed, load and geometry");
  std::vector<char> cavity;  // each solve starts from the last one's pressurised nodes
  auto magnitude = [&](double eps) {
    const FilmSolution s = filmAt(eps, ld, grid, {}, false, &cavity);
    return std::hypot(s.force[0], s.force[1]);
  };
  // |Fbar| rises monotonically with eps, like eps at light load and like a power of
  // 1 / (1 - eps) at heavy load: its logarithm is nearly linear in u = log(eps / (1 - eps)),
  // where regula falsi (Illinois) converges fast. u is shifted by kShift to stay positive
  // (speedRoot's tolerance is relative to the bracket's upper end).
  constexpr double kLightest = 1e-6, kShift = 20;
  auto epsOf = [](double u) { return 1 / (1 + std::exp(kShift - u)); };
  auto uOf = [](double e) { return std::log(e / (1 - e)) + kShift; };
  auto gap = [&](double u) { return std::log(magnitude(epsOf(u)) / target); };
  const double top = gap(uOf(kFiniteMaxEccentricity));
  if (top < 0)
    throw std::invalid_argument("the film carries the load only at an eccentricity ratio above " +
                                filmRatioText(kFiniteMaxEccentricity));
  double eps = kLightest;
  if (const double bottom = gap(uOf(kLightest)); bottom < 0)
    eps = epsOf(
        speedRoot(gap, uOf(kLightest), bottom, uOf(kFiniteMaxEccentricity), top, 1e-10).speed);
  else
    eps = kLightest * target / magnitude(kLightest);  // linear in eps down there
  const FilmSolution s = filmAt(eps, ld, grid, {}, true, &cavity);
  const double load = std::hypot(s.force[0], s.force[1]);
  // Global axes: the film force on the journal points along +y (it carries the load, which
  // acts towards -y). The frame of the line of centres turns by gamma = -(its force angle).
  const double gamma = -std::atan2(s.force[1], s.force[0]);
  const double cg = std::cos(gamma), sg = std::sin(gamma);
  const double rot[2][2] = {{cg, -sg}, {sg, cg}};
  auto toGlobal = [&](const double(&m)[2][2], double scale) {
    double g[2][2]{};
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j)
        for (int k = 0; k < 2; ++k)
          for (int l = 0; l < 2; ++l) g[i][j] += rot[i][k] * m[k][l] * rot[j][l];
    for (auto& row : g)
      for (double& v : row) v *= scale / load;
    return std::array<double, 4>{g[0][0], g[0][1], g[1][0], g[1][1]};
  };
  JournalOperatingPoint out;
  out.eccentricity = eps;
  // The journal's centre lies towards the thinnest film (theta = pi), the load line at
  // theta_global = pi: the attitude angle is gamma, folded into (-pi, pi].
  out.attitude = std::remainder(gamma, 2 * kPiFilm);
  const double kScale = bearing.load / bearing.clearance;
  const auto k = toGlobal(s.stiffness, kScale);
  const auto c = toGlobal(s.damping, kScale / speed);
  out.coefficients.kyy = k[0];
  out.coefficients.kyz = k[1];
  out.coefficients.kzy = k[2];
  out.coefficients.kzz = k[3];
  out.coefficients.cyy = c[0];
  out.coefficients.cyz = c[1];
  out.coefficients.czy = c[2];
  out.coefficients.czz = c[3];
  return out;
}

}  // namespace beamrotor
