// One pad of a tilting-pad bearing, its film in the pad's own axes (elements/TiltingPadBearing.hpp
// explains them): H = 1 - (m + rho) cos(phi) - s sin(phi) over the pad's arc, the journal at rho
// (/ c_p) towards the pivot and s across the pivot line (the journal less the pad's tilt), and
// the tilt s at which the film's force passes through the pivot (the pad's moment vanishes).
// The equilibrium of the bearing (TiltingPadBearing.cpp) and the nonlinear film of a run-up
// (elements/TiltingPadJournalFilm.hpp) share it: the same film, grid and cavitation.
//
// Squeeze: the journal may move relative to the pad's centre of curvature at (rho', s') / Omega;
// it enters the film as JournalMotion's velocity along the pad's axes (elements/ReynoldsFilm.hpp);
// 0 at equilibrium.
#pragma once

#include <optional>
#include <vector>

#include "elements/ReynoldsFilm.hpp"
#include "elements/TiltingPadBearing.hpp"

namespace beamrotor {

class PadFilm {
 public:
  PadFilm(const TiltingPads& pads, double lengthOverDiameter, const ReynoldsGrid& grid)
      : arc_(pads.arc), offset_(pads.pivotOffset), preload_(pads.preload),
        ld_(lengthOverDiameter), grid_(grid) {}

  /// The film's arc and shape at (rho, s).
  FilmArc shape(double rho, double s) const {
    return {-offset_ * arc_, arc_, -(preload_ + rho), -s};
  }
  /// The film at rest at (rho, s).
  FilmSolution solve(double rho, double s, bool withCoefficients);
  /// The film at (rho, s) moving at (rho', s') / Omega = `rates`, with its coefficients.
  FilmSolution solveMoving(double rho, double s, const double rates[2]);
  /// The thinnest film (/ c_p) over the pad's nodes.
  double thinnest(double rho, double s) const;

  /// A first guess for the next tilt (s), as the last root found would be.
  void seed(double s) { lastRoot_ = s; }
  /// The pad's tilt at rho: s where the film's force passes through the pivot, or none for a
  /// pad the journal has left (m + rho <= 0: its film no longer narrows towards the pivot and
  /// carries nothing at any tilt that keeps the force on the pivot). The film stays positive for
  /// s inside (low, high) (it closes at the trailing edge at `high`); near `high` the pressure
  /// gathers at the trailing edge (f . t < 0); at s = 0 with m + rho > 0 the film is thinnest at
  /// the pivot and the pressure lies ahead of it (f . t > 0): the root lies between.
  std::optional<double> equilibriumTilt(double rho);

 private:
  std::optional<double> newtonTilt(double rho, double s, double low, double high);

  FilmSolution solveAt(double rho, double s, const JournalMotion& motion, bool withCoefficients);

  /// The last film solved with its coefficients, and where: balance() asks for the one
  /// newtonTilt ended on.
  struct Solved {
    double rho, s, rate0, rate1;
    FilmSolution film;
  };
  std::optional<Solved> last_;
  double arc_, offset_, preload_, ld_;
  ReynoldsGrid grid_;
  std::vector<char> cavity_;  ///< the last film's pressurised nodes, the next one's first guess
  std::optional<double> lastRoot_;  ///< the last tilt found
};

}  // namespace beamrotor
