// The standard benchmark models, built the same way every time so figures compare run to run.
#pragma once

#include <memory>

#include "fem/Model.hpp"

namespace beamrotor {

/// A long continuous planar Euler-Bernoulli beam: steel (E = 210e9, rho = 7850), 20 mm square
/// section, spans of 0.6 m with 10 elements each, pinned (ux = uy = 0) at every span end,
/// uniform load 1000 N/m downwards. `elements` is rounded up to whole spans.
struct PlanarBenchModel {
  std::unique_ptr<Model> model;
  int spans = 0;
  int midspanNode = -1;          ///< midspan of the middle span
  double exactMidspanW = 0;      ///< q s^4 / (384 E I), downwards negative (m)
  double exactLowestHz = 0;      ///< simply supported span: pi / (2 s^2) sqrt(E I / (rho A))
};
PlanarBenchModel planarBenchModel(int elements);

}  // namespace beamrotor
