// Display scaling of mode shapes (see ModeShapes.hpp).
#include "problems/output/structure/ModeShapes.hpp"

#include <cmath>
#include <utility>

namespace beamrotor {

namespace {

/// Bounding-box diagonal of the nodes (m): turns a rotation (rad) into a translation scale.
double modelSize(const Model& model) {
  if (model.nodes().empty()) return 0;
  Eigen::Vector3d lo = model.nodes().front(), hi = lo;
  for (const auto& x : model.nodes()) {
    lo = lo.cwiseMin(x);
    hi = hi.cwiseMax(x);
  }
  return (hi - lo).norm();
}

/// The entry of largest magnitude among the given columns (0 when the field is empty).
double largestEntry(const NodalField& f, int firstColumn) {
  double best = 0;
  for (int n = 0; n < f.rows(); ++n)
    for (int c = firstColumn; c < firstColumn + 3; ++c)
      if (std::abs(f(n, c)) > std::abs(best)) best = f(n, c);
  return best;
}

/// The largest nodal translation |(ux, uy, uz)| and rotation |(rx, ry, rz)| of a shape.
std::pair<double, double> largestMotions(const NodalField& shape) {
  double translation = 0, rotation = 0;
  for (int n = 0; n < shape.rows(); ++n) {
    translation = std::max(translation, shape.row(n).head<3>().norm());
    rotation = std::max(rotation, shape.row(n).tail<3>().norm());
  }
  return {translation, rotation};
}

/// Of the three kinds from `first` (0: translations, 3: rotations), the one with the largest
/// magnitude anywhere in the shape.
Dof dominantKind(const NodalField& shape, int first) {
  int best = first;
  double largest = -1;
  for (int c = first; c < first + 3; ++c) {
    const double m = shape.rows() ? shape.col(c).cwiseAbs().maxCoeff() : 0;
    if (m > largest) {
      largest = m;
      best = c;
    }
  }
  return kAllDofs[best];
}

}  // namespace

bool isTorsionalShape(const Model& model, const NodalField& shape) {
  const auto [translation, rotation] = largestMotions(shape);
  return rotation > 0 && translation <= 1e-9 * rotation * std::max(modelSize(model), 1.0);
}

NodalField displayModeShape(const Model& model, const NodalField& shape) {
  const auto [translation, rotation] = largestMotions(shape);
  const bool torsional = isTorsionalShape(model, shape);
  const double size = torsional ? rotation : translation;
  if (size == 0) return shape;
  const double sign = largestEntry(shape, torsional ? 3 : 0) < 0 ? -1.0 : 1.0;
  return shape * (sign / size);
}

Dof dominantTranslation(const NodalField& shape) {
  return dominantKind(shape, 0);
}

Dof chartedDof(const Model& model, const NodalField& shape) {
  return isTorsionalShape(model, shape) ? dominantKind(shape, 3) : dominantKind(shape, 0);
}

}  // namespace beamrotor
