// VTK XML writers (see VtkWriter.hpp) built on vtkUnstructuredGrid and its XML writer.
#include "problems/output/structure/VtkWriter.hpp"

#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <algorithm>
#include <array>
#include <stdexcept>
#include <string>
#include <vector>

#include "fem/assembly/Recovery.hpp"
#include "problems/output/files/CsvTable.hpp"
#include "problems/output/files/FileWriting.hpp"
#include "problems/output/structure/ModeShapes.hpp"
#include "problems/output/files/VtkGrid.hpp"
#include "problems/output/files/XmlText.hpp"

namespace beamrotor {

vtkSmartPointer<vtkDoubleArray> doubleArray(const char* name, int components, vtkIdType tuples) {
  auto a = vtkSmartPointer<vtkDoubleArray>::New();
  a->SetName(name);
  a->SetNumberOfComponents(components);
  a->SetNumberOfTuples(tuples);
  return a;
}

/// The line elements of a model, in element order (the VTK cell order).
std::vector<const LineElement*> lineElements(const Model& model, std::vector<int>* indices) {
  std::vector<const LineElement*> lines;
  for (int i = 0; i < int(model.elements().size()); ++i)
    if (const auto* line = model.elements()[i]->asLineElement()) {
      lines.push_back(line);
      indices->push_back(i);
    }
  return lines;
}

/// The element's local triad as cell vectors local_x, local_y, local_z, the distances to the
/// outer fibres along local y and z (outer_y, outer_z; m) per cell, and per point the
/// largest outer distance of the elements meeting there (tube_radius, m): ParaView's Tube
/// filter with "Vary Radius: By Absolute Scalar" on it draws the members at their true size,
/// and Glyph on the triad shows how each member is turned.
namespace {

void addSectionGeometry(vtkUnstructuredGrid& grid, const std::vector<const LineElement*>& lines) {
  const vtkIdType cells = vtkIdType(lines.size());
  std::array<vtkSmartPointer<vtkDoubleArray>, 3> axes{doubleArray("local_x", 3, cells),
                                                      doubleArray("local_y", 3, cells),
                                                      doubleArray("local_z", 3, cells)};
  auto outerY = doubleArray("outer_y", 1, cells), outerZ = doubleArray("outer_z", 1, cells);
  auto radius = doubleArray("tube_radius", 1, grid.GetNumberOfPoints());
  radius->Fill(0);
  for (vtkIdType c = 0; c < cells; ++c) {
    const Eigen::Matrix3d R = lines[c]->localAxes();
    for (int k = 0; k < 3; ++k) axes[k]->SetTuple3(c, R(k, 0), R(k, 1), R(k, 2));
    const Section& s = lines[c]->section();
    outerY->SetValue(c, s.outerY);
    outerZ->SetValue(c, s.outerZ);
    for (int node : lines[c]->endNodes())
      radius->SetValue(node, std::max(radius->GetValue(node), std::max(s.outerY, s.outerZ)));
  }
  for (const auto& a : axes) grid.GetCellData()->AddArray(a);
  grid.GetCellData()->AddArray(outerY);
  grid.GetCellData()->AddArray(outerZ);
  grid.GetPointData()->AddArray(radius);
}

}  // namespace

/// Points, VTK_LINE cells and the cell data every file carries (element index, section).
vtkSmartPointer<vtkUnstructuredGrid> lineGrid(const Model& model) {
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (const Eigen::Vector3d& x : model.nodes()) points->InsertNextPoint(x.x(), x.y(), x.z());
  grid->SetPoints(points);

  std::vector<int> indices;
  const auto lines = lineElements(model, &indices);
  const vtkIdType cells = vtkIdType(lines.size());
  grid->Allocate(cells);
  vtkNew<vtkIntArray> element;
  element->SetName("element");
  element->SetNumberOfTuples(cells);
  auto A = doubleArray("A", 1, cells), Iy = doubleArray("Iy", 1, cells),
       Iz = doubleArray("Iz", 1, cells), E = doubleArray("E", 1, cells);
  for (vtkIdType c = 0; c < cells; ++c) {
    const auto [n1, n2] = lines[c]->endNodes();
    const vtkIdType ends[2] = {n1, n2};
    grid->InsertNextCell(VTK_LINE, 2, ends);
    element->SetValue(c, indices[c]);
    const Section& s = lines[c]->section();
    A->SetValue(c, s.A);
    Iy->SetValue(c, s.Iy);
    Iz->SetValue(c, s.Iz);
    E->SetValue(c, s.material.E);
  }
  grid->GetCellData()->AddArray(element);
  for (vtkDoubleArray* a : {A.Get(), Iy.Get(), Iz.Get(), E.Get()}) grid->GetCellData()->AddArray(a);
  addSectionGeometry(*grid, lines);
  return grid;
}

void addTieCells(vtkUnstructuredGrid& grid, const Model& model) {
  const vtkIdType own = grid.GetNumberOfCells();
  const auto& ties = model.rigidTies();
  vtkNew<vtkIntArray> kind;
  kind->SetName("kind");
  kind->SetNumberOfTuples(own + vtkIdType(ties.size()));
  for (vtkIdType c = 0; c < own; ++c) kind->SetValue(c, 0);
  vtkCellData& data = *grid.GetCellData();
  for (const RigidTie& t : ties) {
    const vtkIdType ends[2] = {t.master, t.slave};
    kind->SetValue(grid.InsertNextCell(VTK_LINE, 2, ends), 1);
    for (int a = 0; a < data.GetNumberOfArrays(); ++a) {
      vtkDataArray& array = *data.GetArray(a);
      const std::vector<double> none(std::size_t(array.GetNumberOfComponents()),
                                     std::string(array.GetName()) == "element" ? -1.0 : 0.0);
      array.InsertNextTuple(none.data());
    }
  }
  data.AddArray(kind);
}

/// Columns [first, first + 3) of a nodal field as a 3-component point array.
vtkSmartPointer<vtkDoubleArray> pointVectors(const char* name, const NodalField& field, int first) {
  auto a = doubleArray(name, 3, field.rows());
  for (int n = 0; n < field.rows(); ++n)
    a->SetTuple3(n, field(n, first), field(n, first + 1), field(n, first + 2));
  return a;
}

void writeVtu(vtkUnstructuredGrid* grid, const std::filesystem::path& file) {
  vtkNew<vtkXMLUnstructuredGridWriter> writer;
  // Into memory, then through writeFile: VTK's own file writing does not report every
  // failed write (a full device).
  writer->WriteToOutputStringOn();
  writer->SetInputData(grid);
  // Inline base64 with zlib compression: compact, and read by ParaView, VTK and meshio alike.
  // zlib's fastest level: the 5,320-element frame's file is written in 19 ms of CPU instead of
  // 28 ms at VTK's default (5), 3.5 % larger (doubles compress little at any level).
  writer->SetDataModeToBinary();
  writer->SetCompressorTypeToZLib();
  writer->SetCompressionLevel(1);
  if (writer->Write() != 1) throw std::runtime_error("VTK could not write " + file.string());
  const std::string text = writer->GetOutputString();
  writeFile(file, [&](std::ostream& out) { out << text; });
}

namespace {

/// Forces at nodes (reactions, or springs' forces) summed per node and component as two
/// 3-component point arrays, `<what>_force` (fx fy fz) and `<what>_moment` (mx my mz).
void addNodalForces(vtkUnstructuredGrid& grid, const std::vector<ReactionComponent>& forces,
                    const std::string& what) {
  const vtkIdType points = grid.GetNumberOfPoints();
  auto force = doubleArray((what + "_force").c_str(), 3, points);
  auto moment = doubleArray((what + "_moment").c_str(), 3, points);
  force->Fill(0);
  moment->Fill(0);
  for (const ReactionComponent& f : forces) {
    if (f.node < 0 || f.node >= points) continue;
    const int k = int(f.dof);
    vtkDoubleArray& a = k < 3 ? *force : *moment;
    a.SetComponent(f.node, k % 3, a.GetComponent(f.node, k % 3) + f.value);
  }
  grid.GetPointData()->AddArray(force);
  grid.GetPointData()->AddArray(moment);
}

}  // namespace

void writeStaticVtu(const std::filesystem::path& file, const LoadedSolution& solution,
                    const StaticResult& statics, const std::vector<StaticStation>& stations,
                    const std::vector<ElementPeaks>& peaks) {
  const Model& model = *solution.model;
  auto grid = lineGrid(model);
  grid->GetPointData()->AddArray(pointVectors("displacement", *solution.displacement, 0));
  grid->GetPointData()->AddArray(pointVectors("rotation", *solution.displacement, 3));
  addNodalForces(*grid, statics.reactions, "reaction");
  addNodalForces(*grid, statics.elementForces, "spring");

  // Section forces at mid-length: recovery with two intervals puts station 1 of 3 there.
  const std::vector<BeamStation> mid = recoverBeamFields(solution, 2);
  const vtkIdType cells = grid->GetNumberOfCells();
  if (vtkIdType(mid.size()) != 3 * cells) throw std::logic_error("mid-length stations missing");
  const char* names[] = {"N", "Vy", "Vz", "T", "My", "Mz"};
  std::vector<vtkSmartPointer<vtkDoubleArray>> forces;
  for (const char* name : names) forces.push_back(doubleArray(name, 1, cells));
  for (vtkIdType c = 0; c < cells; ++c) {
    const SectionForces& f = mid[3 * c + 1].forces;
    const double values[] = {f.N, f.Vy, f.Vz, f.T, f.My, f.Mz};
    for (int k = 0; k < 6; ++k) forces[k]->SetValue(c, values[k]);
  }
  for (auto& a : forces) grid->GetCellData()->AddArray(a);

  // Each element's own end rotations: at a hinge they differ from the node's (which may carry
  // no rotation at all), and a point holds only one value.
  auto* element = grid->GetCellData()->GetArray("element");
  std::vector<int> cellOf(model.elements().size(), -1);
  for (vtkIdType c = 0; c < cells; ++c) cellOf.at(int(element->GetTuple1(c))) = int(c);
  auto start = doubleArray("rotation_start", 3, cells), end = doubleArray("rotation_end", 3, cells);
  for (const StaticStation& st : stations)
    if (st.place.s == 0 || st.place.s == 1)
      (st.place.s == 0 ? start : end)
          ->SetTuple3(cellOf.at(st.place.element), st.displacement[3], st.displacement[4],
                      st.displacement[5]);
  grid->GetCellData()->AddArray(start);
  grid->GetCellData()->AddArray(end);

  // Each element's exact largest normal and shear stress.
  std::vector<const ElementPeaks*> peakOf(model.elements().size(), nullptr);
  for (const ElementPeaks& p : peaks) peakOf.at(p.stress.element) = &p;
  for (const auto& [name, kind] :
       {std::pair{"stress", &ElementPeaks::stress}, std::pair{"shear", &ElementPeaks::shear}}) {
    auto array = doubleArray(name, 1, cells);
    for (vtkIdType c = 0; c < cells; ++c) {
      const ElementPeaks* p = peakOf.at(int(element->GetTuple1(c)));
      if (!p) throw std::logic_error("an element without peaks");
      array->SetValue(c, (p->*kind).value);
    }
    grid->GetCellData()->AddArray(array);
  }
  addTieCells(*grid, model);
  writeVtu(grid, file);
}

void writeModeVtu(const std::filesystem::path& file, const Model& model, const Mode& mode,
                  int number) {
  writeShapeVtu(file, model, mode.shape, number, "frequency_hz", mode.frequencyHz);
}

void writeShapeVtu(const std::filesystem::path& file, const Model& model, const NodalField& raw,
                   int number, const std::string& valueName, double value) {
  auto grid = lineGrid(model);
  const NodalField shape = displayModeShape(model, raw);
  grid->GetPointData()->AddArray(pointVectors("mode_shape", shape, 0));
  grid->GetPointData()->AddArray(pointVectors("mode_rotation", shape, 3));
  vtkNew<vtkIntArray> modeNumber;
  modeNumber->SetName("mode");
  modeNumber->InsertNextValue(number);
  auto modeValue = doubleArray(valueName.c_str(), 1, 1);
  modeValue->SetValue(0, value);
  grid->GetFieldData()->AddArray(modeNumber);
  grid->GetFieldData()->AddArray(modeValue);
  addTieCells(*grid, model);
  writeVtu(grid, file);
}

void writeFrameVtu(const std::filesystem::path& file, const Model& model, const Frame& frame) {
  auto grid = lineGrid(model);
  if (grid->GetNumberOfCells() == 0) {
    grid->GetCellData()->Initialize();  // the line arrays (empty) would not match the vertices
    for (vtkIdType n = 0; n < vtkIdType(model.nodeCount()); ++n)
      grid->InsertNextCell(VTK_VERTEX, 1, &n);
  }
  grid->GetPointData()->AddArray(pointVectors("displacement", frame.displacement, 0));
  grid->GetPointData()->AddArray(pointVectors("rotation", frame.displacement, 3));
  auto time = doubleArray("time", 1, 1);
  time->SetValue(0, frame.time);
  grid->GetFieldData()->AddArray(time);
  addTieCells(*grid, model);
  writeVtu(grid, file);
}

void writePvd(const std::filesystem::path& file, const std::vector<PvdEntry>& entries) {
  writeFile(file, [&](std::ostream& out) {
    out << "<?xml version=\"1.0\"?>\n"
        << "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
        << "  <Collection>\n";
    for (const PvdEntry& e : entries)
      out << "    <DataSet timestep=\"" << exactDecimal(e.timestep)
          << "\" group=\"\" part=\"0\" file=\"" << xmlEscape(e.file) << "\"/>\n";
    out << "  </Collection>\n</VTKFile>\n";
  });
}

}  // namespace beamrotor
