// The envelopes of a whole model's response under a train of loads crossing a path: every
// node's six displacements and every line element's six resultants at both its ends, each as
// an exact influence line (InfluenceLines.hpp) run through the exact train envelope
// (TrainEnvelope.hpp), with a static part (the deck's own loads) added to both extremes.
#pragma once

#include <array>
#include <vector>

#include "fem/model/Model.hpp"
#include "fem/model/Results.hpp"
#include "fem/static/InfluenceLines.hpp"
#include "fem/static/TrainEnvelope.hpp"

namespace beamrotor {

struct FieldEnvelopes {
  /// Per node, per dof kind (ux uy uz rx ry rz): m, rad.
  std::vector<std::array<TrainEnvelope, kDofKinds>> nodes;
  /// Per element of the model, per end (start, end), per component in kForceComponents'
  /// order (N Vy Vz T My Mz, element frame): N, N m. Elements that are not line elements hold
  /// zeros.
  std::vector<std::array<std::array<TrainEnvelope, 6>, 2>> elementEnds;
};

/// The envelopes under `train` of `units` (solved on `model`), plus `still` (a static
/// solution of the same model whose values are added to both extremes; null: none).
FieldEnvelopes fieldEnvelopes(const Model& model, const PathUnitLoads& units,
                              const std::vector<TrainLoad>& train, const StaticResult* still);

}  // namespace beamrotor
