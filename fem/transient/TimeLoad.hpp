// Loads as functions of time for transient analysis: scalar functions of time (piecewise,
// harmonic series, tabulated, periodic repetition) and the loads built from them, each a fixed
// spatial pattern of nodal forces scaled by one such function.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "fem/model/Dof.hpp"
#include "fem/model/Model.hpp"

namespace beamrotor {

/// A scalar function of time t (s). What it returns is dimensionless when it scales a load
/// pattern, or in the units of the quantity it describes (m, m/s, m/s^2 for support motion).
using TimeFunction = std::function<double(double)>;

/// One piece of a piecewise function: `f` applies from `start` (s) up to the next piece's
/// start. `f` is called with the same time t the piecewise function receives (not the time
/// since `start`), so a piece written as H sin(mu t) means exactly that.
struct TimePiece {
  double start = 0;
  TimeFunction f;
};

/// One term A cos(k omega t + phase) of a harmonic series.
struct Harmonic {
  int k = 1;             ///< multiple of the fundamental
  double amplitude = 0;  ///< in the units of the series
  double phase = 0;      ///< rad
};

namespace timefn {

/// f(t) = value.
TimeFunction constant(double value);
/// f(t) = amplitude sin(omega t + phase), omega in rad/s, phase in rad.
TimeFunction sine(double amplitude, double omega, double phase = 0);
/// Pieces in strictly ascending start; f(t) = 0 before the first start. Throws
/// std::invalid_argument for an empty list, unsorted starts or an empty function.
TimeFunction piecewise(std::vector<TimePiece> pieces);
/// f(t) = mean + sum_k A_k cos(k omega t + phase_k), omega (rad/s) the fundamental.
TimeFunction harmonicSeries(double omega, std::vector<Harmonic> terms, double mean = 0);
/// Linear interpolation in a table of (time, value), times strictly ascending; the first and
/// last values are held outside the table. Throws std::invalid_argument for fewer than one
/// point, sizes that differ or times out of order.
TimeFunction tabulated(std::vector<double> times, std::vector<double> values);
/// f(t) = g(t - start - n period) with n chosen so the argument lies in [0, period): g's
/// definition on [0, period) repeated for ever (before `start` too). period > 0 (s).
TimeFunction periodic(TimeFunction g, double period, double start = 0);

}  // namespace timefn

/// A load varying in time: a fixed spatial pattern (forces N, moments N m, global frame, per
/// unit of the factor) times a scalar function of time.
struct TimeLoad {
  std::string name;
  std::vector<NodalLoad> pattern;
  TimeFunction factor;
};

/// A one-entry pattern at a named point: value (N or N m) times factor(t) on that point's dof.
/// Throws std::out_of_range for an unknown point name.
TimeLoad pointTimeLoad(const Model& model, const std::string& point, Dof dof, double value,
                       TimeFunction factor, std::string name = {});

}  // namespace beamrotor
