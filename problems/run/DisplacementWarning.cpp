#include "problems/run/DisplacementWarning.hpp"

#include <Eigen/Core>
#include <cstdio>

namespace beamrotor {

std::optional<std::string> displacementWarning(const Model& model, const StaticResult& r) {
  const auto& nodes = model.nodes();
  if (nodes.empty() || r.displacement.rows() != Eigen::Index(nodes.size())) return std::nullopt;
  const double size = model.size();
  if (!(size > 0)) return std::nullopt;
  Eigen::Index worst = 0;
  double largest = 0;
  for (Eigen::Index i = 0; i < r.displacement.rows(); ++i) {
    const double u = r.displacement.row(i).head<3>().norm();
    if (u > largest) largest = u, worst = i;
  }
  if (!(largest > size)) return std::nullopt;
  const Eigen::Vector3d& at = nodes[std::size_t(worst)];
  char text[400];
  std::snprintf(text, sizeof text,
                "displacement %.3g m at node %d (x = %.4g m) exceeds the structure's own size "
                "(%.3g m): a linear static analysis is meaningless there; check the units of "
                "the materials' E, the sections and the loads (bare numbers are SI: write "
                "`E: 210 GPa`)",
                largest, int(worst), at.x(), size);
  return std::string(text);
}

}  // namespace beamrotor
