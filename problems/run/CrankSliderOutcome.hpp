// A crank-slider analysis, solved (problems/scenes/README.md section 3): the motion of the
// first crank's slider and rod over one revolution, the figures of the mechanism at its crank
// speed, its inertia loads and their balance over all cranks, and the harmonic table.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "problems/deck/crank/DeckCrank.hpp"
#include "problems/scenes/CrankSlider.hpp"

namespace beamrotor {

/// One row of the harmonic table (the SNT-32 paper's Table 2 layout).
struct CrankLambdaRow {
  double lambda = 0;
  crank::SeriesCoefficients series;
  double vRatio = 0;   ///< v_max / v_mean, exact kinematics
  double kLambda = 0;  ///< K in a_max = K r n^2 with n in rpm: (pi/30)^2 (1 + lambda)
};

/// One sample of the revolution: the first crank's slider and rod, exact and two-term.
struct CrankSample {
  crank::State exact;
  crank::State approximate;
  double inertiaForce = 0;  ///< first crank's reciprocating inertia force -m_rec a (N), exact
  double cranksForce = 0;   ///< sum of the cranks' reciprocating inertia forces (N), exact
  double rodCouple = 0;     ///< first crank's rod correction couple (N m), exact
};

struct CrankSliderOutcome {
  DeckCrankSlider input;
  std::vector<CrankSample> samples;  ///< phi = 2 pi i / steps, i = 0 .. steps

  double lambda = 0;
  double vMax = 0, vMean = 0, aMax = 0;  ///< exact, at the crank speed (m/s, m/s^2)
  double betaMax = 0;                    ///< asin(lambda) (rad)
  double betaDotMax = 0;                 ///< omega lambda (1/s)
  double betaDDotMax = 0;                ///< omega^2 lambda / sqrt(1 - lambda^2) (1/s^2)
  double betaDDotMaxFirstOrder = 0;      ///< omega^2 lambda
  crank::SeriesCoefficients series;

  std::optional<crank::ReducedMasses> reduced;  ///< when the deck gave masses
  /// Per crank: amplitudes (N) of the reciprocating inertia force's cos(k phi) terms for
  /// k = 1, 2, 4, 6 (magnitudes), and the rotating mass' centrifugal force.
  std::array<double, 4> harmonics{};
  double rotatingForce = 0;
  /// Over all cranks (parallel cylinders, cranks on one shaft): amplitude of the resultant of
  /// each order k = 1, 2, 4, 6, F_k |sum_j exp(i k theta_j)|, and of the rotating forces.
  std::array<double, 4> cranksHarmonics{};
  double cranksRotating = 0;
  double momentMax = 0, momentMaxFirstOrder = 0;  ///< rod correction couple amplitude (N m)
  double delivery = 0;                            ///< m^3/s; 0 without a plunger

  std::vector<CrankLambdaRow> table;
};

}  // namespace beamrotor
