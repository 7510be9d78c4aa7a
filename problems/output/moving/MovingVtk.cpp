#include "problems/output/moving/MovingVtk.hpp"

#include <vtkCellData.h>
#include <vtkFieldData.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>

#include <algorithm>

#include "fem/assembly/MemberExtrema.hpp"
#include "problems/output/files/VtkGrid.hpp"

namespace beamrotor {

namespace {

/// The point array of one side (max or min) of three dof kinds' envelopes from `first`.
vtkSmartPointer<vtkDoubleArray> nodalSide(const std::string& name, const FieldEnvelopes& f,
                                          int first, bool largest) {
  auto a = doubleArray(name.c_str(), 3, vtkIdType(f.nodes.size()));
  for (std::size_t n = 0; n < f.nodes.size(); ++n)
    for (int k = 0; k < 3; ++k) {
      const TrainEnvelope& e = f.nodes[n][std::size_t(first + k)];
      a->SetComponent(vtkIdType(n), k, largest ? e.max.value : e.min.value);
    }
  return a;
}

/// The whole model's envelopes: point arrays of the nodes' extremes, cell arrays of each line
/// element's (over both its ends).
void addFieldEnvelopes(vtkUnstructuredGrid& grid, const Model& model, const FieldEnvelopes& f) {
  vtkPointData& points = *grid.GetPointData();
  for (bool largest : {true, false}) {
    const std::string side = largest ? "_max" : "_min";
    points.AddArray(nodalSide("displacement" + side + " [m]", f, 0, largest));
    points.AddArray(nodalSide("rotation" + side + " [rad]", f, 3, largest));
  }

  std::vector<int> indices;
  lineElements(model, &indices);
  const vtkIdType cells = vtkIdType(indices.size());
  for (std::size_t k = 0; k < kForceComponents.size(); ++k) {
    const ForceComponent c = kForceComponents[k];
    const bool moment = c == ForceComponent::T || c == ForceComponent::My || c == ForceComponent::Mz;
    const std::string unit = moment ? " [N m]" : " [N]";
    auto high = doubleArray((std::string(componentName(c)) + "_max" + unit).c_str(), 1, cells);
    auto low = doubleArray((std::string(componentName(c)) + "_min" + unit).c_str(), 1, cells);
    for (vtkIdType cell = 0; cell < cells; ++cell) {
      const auto& ends = f.elementEnds.at(std::size_t(indices[std::size_t(cell)]));
      high->SetValue(cell, std::max(ends[0][k].max.value, ends[1][k].max.value));
      low->SetValue(cell, std::min(ends[0][k].min.value, ends[1][k].min.value));
    }
    grid.GetCellData()->AddArray(high);
    grid.GetCellData()->AddArray(low);
  }
}

}  // namespace

std::string movingVtu(const std::string& stem) { return stem + "_envelope.vtu"; }

void writeMovingVtu(const std::filesystem::path& dir, const Model& model,
                    const MovingLoadOutcome& m, const std::string& stem) {
  auto grid = lineGrid(model);
  vtkPointData& points = *grid->GetPointData();
  if (!m.fields.nodes.empty()) addFieldEnvelopes(*grid, model, m.fields);
  for (const MovingQuantity& q : m.quantities)
    for (bool largest : {true, false}) {
      const std::string of = std::string(largest ? " at max of " : " at min of ") + q.text;
      const NodalField& shape = largest ? q.shapeAtMax : q.shapeAtMin;
      points.AddArray(pointVectors(("displacement" + of + " [m]").c_str(), shape, 0));
      points.AddArray(pointVectors(("rotation" + of + " [rad]").c_str(), shape, 3));
      auto lead = doubleArray(("first wheel" + of + " [m]").c_str(), 1, 1);
      lead->SetValue(0, largest ? q.envelope.max.lead : q.envelope.min.lead);
      grid->GetFieldData()->AddArray(lead);
    }
  addTieCells(*grid, model);
  writeVtu(grid, dir / movingVtu(stem));
}

}  // namespace beamrotor
