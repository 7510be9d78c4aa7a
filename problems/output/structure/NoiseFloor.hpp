// The magnitudes below which a static solution's numbers carry no trusted digit. A value that
// should vanish (a symmetric frame's out-of-plane reaction, an unloaded member's shear) comes
// out of the solve as round-off, 1e-15 N beside 5000 N; the summary shows such values as 0.
// Each kind is judged against the largest of its own kind in the same solution, so the floor
// is the same in any units: the solve's measured relative error (StaticResult::roundOff, or
// kNegligibleShare when that is smaller) times the kind's scale.
#pragma once

#include <cmath>

#include "fem/model/Dof.hpp"
#include "fem/model/Model.hpp"
#include "fem/model/Results.hpp"
#include "problems/output/structure/CaseEnvelope.hpp"
#include "problems/output/structure/StaticExtremes.hpp"

namespace beamrotor {

/// The smallest share of its kind's largest value that a shown number keeps: the recovery of
/// forces from displacements sums terms as large as the largest force, so a share below
/// about 1e-12 is already beyond double precision's trusted digits on element sums.
inline constexpr double kNegligibleShare = 1e-12;

/// `value`, or 0 when its magnitude is at or below `floor`.
inline double zeroAtOrBelow(double value, double floor) {
  return std::abs(value) <= floor ? 0.0 : value;
}

struct NoiseFloor {
  double translation = 0;  ///< m
  double rotation = 0;     ///< rad
  double force = 0;        ///< N
  double moment = 0;       ///< N m
  double stress = 0;       ///< Pa, normal or shear

  /// `value`, or 0 when its magnitude is at or below the floor of a displacement along `d`.
  double motion(double value, Dof d) const;
  /// `value`, or 0 when its magnitude is at or below the floor of a force (moment when
  /// `isMoment`).
  double load(double value, bool isMoment) const;
};

/// The floors of solution `r` of `model`, with its member extremes when there are members.
/// Scales: translations, the largest nodal translation; rotations, the largest rotation or
/// the largest translation over the model's size; forces, the largest reaction, spring force or
/// member force (N, Vy, Vz); moments, the largest of their own kind or the force scale times
/// the model's size; stresses, the largest normal or shear stress of the extremes' peaks.
NoiseFloor noiseFloorOf(const Model& model, const StaticResult& r,
                        const StaticExtremes* extremes = nullptr);

/// The floors of an envelope over combinations whose solves measured at most `roundOff`: the
/// same scales taken from the envelope's own largest values (translations from its largest
/// displacement; rotations are not enveloped).
NoiseFloor noiseFloorOf(const Model& model, const CaseEnvelope& envelope, double roundOff);

}  // namespace beamrotor
