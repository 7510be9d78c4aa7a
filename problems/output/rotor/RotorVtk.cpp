// VTK files of damped rotor modes (see RotorVtk.hpp).
#include "problems/output/rotor/RotorVtk.hpp"

#include <vtkCellData.h>
#include <vtkFieldData.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>

#include <numbers>

#include "problems/output/rotor/RotorTables.hpp"
#include "problems/output/files/VtkGrid.hpp"

namespace beamrotor {

namespace {

/// Points drawn per orbit.
constexpr int kOrbitPoints = 48;
/// Orbits are drawn this fraction of the model's extent across.
constexpr double kOrbitScale = 0.1;

Orbit orbitAt(const RotorMode& mode, int node) {
  return {mode.shape(node, dofIndex(Dof::uy)), mode.shape(node, dofIndex(Dof::uz))};
}

void addField(vtkUnstructuredGrid* grid, const char* name, double value) {
  auto a = doubleArray(name, 1, 1);
  a->SetValue(0, value);
  grid->GetFieldData()->AddArray(a);
}

}  // namespace

void writeRotorModeVtu(const std::filesystem::path& file, const Model& model, const RotorMode& mode,
                       int number) {
  auto grid = lineGrid(model);
  const NodalField real = mode.shape.real(), imag = mode.shape.imag();
  grid->GetPointData()->AddArray(pointVectors("shape_real", real, 0));
  grid->GetPointData()->AddArray(pointVectors("shape_imag", imag, 0));
  grid->GetPointData()->AddArray(pointVectors("rotation_real", real, 3));
  grid->GetPointData()->AddArray(pointVectors("rotation_imag", imag, 3));
  auto major = doubleArray("orbit_semi_major", 1, model.nodeCount());
  auto ratio = doubleArray("whirl_ratio", 1, model.nodeCount());
  for (int n = 0; n < model.nodeCount(); ++n) {
    major->SetValue(n, orbitAt(mode, n).major());
    ratio->SetValue(n, orbitAt(mode, n).whirlRatio());
  }
  grid->GetPointData()->AddArray(major);
  grid->GetPointData()->AddArray(ratio);
  vtkNew<vtkIntArray> modeNumber, whirl;
  modeNumber->SetName("mode");
  modeNumber->InsertNextValue(number);
  whirl->SetName("whirl");
  whirl->InsertNextValue(int(whirlSign(mode.whirl)));
  grid->GetFieldData()->AddArray(modeNumber);
  grid->GetFieldData()->AddArray(whirl);
  addField(grid, "frequency_hz", mode.dampedFrequencyHz);
  addField(grid, "natural_frequency_hz", mode.naturalFrequencyHz);
  addField(grid, "damping_ratio", mode.dampingRatio);
  writeVtu(grid, file);
}

void writeOrbitVtu(const std::filesystem::path& file, const Model& model, const RotorMode& mode) {
  // 1. The drawing scale: a tenth of the model's extent for the largest translation (1).
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(0), hi = lo;
  for (int n = 0; n < model.nodeCount(); ++n) {
    lo = n ? lo.cwiseMin(model.nodes()[n]) : model.nodes()[n];
    hi = n ? hi.cwiseMax(model.nodes()[n]) : model.nodes()[n];
  }
  const double scale = kOrbitScale * std::max((hi - lo).norm(), 1e-3);

  // 2. Per node a closed ring of VTK_LINE cells through x + s Re(u e^{i theta}) (lines
  //    rather than one VTK_POLY_LINE, which meshio cannot read).
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkIntArray> nodeIds;
  nodeIds->SetName("node");
  const vtkIdType cells = vtkIdType(model.nodeCount()) * kOrbitPoints;
  auto major = doubleArray("orbit_semi_major", 1, cells);
  grid->Allocate(cells);
  for (int n = 0; n < model.nodeCount(); ++n) {
    const vtkIdType first = points->GetNumberOfPoints();
    for (int j = 0; j < kOrbitPoints; ++j) {
      const std::complex<double> turn = std::polar(1.0, 2 * std::numbers::pi * j / kOrbitPoints);
      Eigen::Vector3d x = model.nodes()[n];
      for (int k = 0; k < 3; ++k) x[k] += scale * (mode.shape(n, k) * turn).real();
      points->InsertNextPoint(x.x(), x.y(), x.z());
    }
    for (int j = 0; j < kOrbitPoints; ++j) {
      const vtkIdType ends[2] = {first + j, first + (j + 1) % kOrbitPoints};
      const vtkIdType cell = grid->InsertNextCell(VTK_LINE, 2, ends);
      nodeIds->InsertNextValue(n);
      major->SetValue(cell, orbitAt(mode, n).major());
    }
  }
  grid->SetPoints(points);
  grid->GetCellData()->AddArray(nodeIds);
  grid->GetCellData()->AddArray(major);
  writeVtu(grid, file);
}

}  // namespace beamrotor
