#include "problems/output/structure/BaseMotionVtk.hpp"

#include <vtkFieldData.h>
#include <vtkPointData.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "problems/output/files/VtkGrid.hpp"

namespace beamrotor {

std::string baseMotionVtu(const std::string& stem) { return stem + "_base_motion_peak.vtu"; }

std::size_t peakPoint(const BaseMotionResult& r) {
  if (r.points.empty()) throw std::invalid_argument("a base-motion sweep without frequencies");
  std::size_t peak = 0;
  for (std::size_t i = 1; i < r.points.size(); ++i)
    if (std::abs(r.points[i].baseForce) > std::abs(r.points[peak].baseForce)) peak = i;
  return peak;
}

void writeBaseMotionVtu(const std::filesystem::path& dir, const Model& model,
                        const BaseMotionResult& r, const std::string& stem) {
  const BaseMotionPoint& p = r.points[peakPoint(r)];
  const int direction = r.options.direction;
  auto grid = lineGrid(model);
  const vtkIdType nodes = grid->GetNumberOfPoints();
  auto relative = doubleArray("relative amplitude [m]", 3, nodes);
  auto absolute = doubleArray("absolute amplitude [m]", 3, nodes);
  auto rotation = doubleArray("rotation amplitude [rad]", 3, nodes);
  auto transmissibility = doubleArray("transmissibility [1]", 1, nodes);
  auto phase = doubleArray("phase [deg]", 1, nodes);
  for (vtkIdType n = 0; n < nodes; ++n) {
    const int node = int(n);
    for (int k = 0; k < 3; ++k) {
      relative->SetComponent(n, k, std::abs(p.relative(node, k)));
      absolute->SetComponent(n, k, std::abs(k == direction ? p.absolute(node, k) : p.relative(node, k)));
      rotation->SetComponent(n, k, std::abs(p.relative(node, 3 + k)));
    }
    transmissibility->SetValue(n, p.transmissibility(node, direction));
    // The absolute acceleration -w^2 u_abs against the ground's (phase 0).
    phase->SetValue(n, std::arg(-p.absolute(node, direction)) * 180 / std::numbers::pi);
  }
  for (vtkDoubleArray* a : {relative.Get(), absolute.Get(), rotation.Get(),
                            transmissibility.Get(), phase.Get()})
    grid->GetPointData()->AddArray(a);
  auto frequency = doubleArray("frequency [Hz]", 1, 1);
  frequency->SetValue(0, p.frequencyHz);
  auto force = doubleArray("base force [N]", 1, 1);
  force->SetValue(0, std::abs(p.baseForce));
  grid->GetFieldData()->AddArray(frequency);
  grid->GetFieldData()->AddArray(force);
  addTieCells(*grid, model);
  writeVtu(grid, dir / baseMotionVtu(stem));
}

}  // namespace beamrotor
