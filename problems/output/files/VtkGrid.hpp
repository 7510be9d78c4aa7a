// The building blocks of the VTK writers (VtkWriter.cpp, RotorVtk.cpp): the model's line
// elements as an unstructured grid, typed point arrays, and writing a grid as .vtu.
#pragma once

#include <vtkDoubleArray.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>

#include <filesystem>
#include <vector>

#include "fem/model/LineElement.hpp"
#include "fem/model/Model.hpp"
#include "fem/model/Results.hpp"

namespace beamrotor {

/// A named double array of `tuples` tuples with `components` components each.
vtkSmartPointer<vtkDoubleArray> doubleArray(const char* name, int components, vtkIdType tuples);

/// The line elements of a model, in element order (the VTK cell order); their indices into
/// model.elements() go to `indices`.
std::vector<const LineElement*> lineElements(const Model& model, std::vector<int>* indices);

/// Every node as a point, one VTK_LINE per line element, and the cell data every file carries
/// (element index, section A, Iy, Iz, E).
vtkSmartPointer<vtkUnstructuredGrid> lineGrid(const Model& model);

/// One VTK_LINE per rigid tie of the model (master to follower: rigid links, member end
/// offsets, a diaphragm's points), appended after the grid's cells, so that a warp by the
/// displacement shows the ties moving with the solution. Every cell array gets a tuple for
/// each (zeros; `element` -1), and the cell array `kind` tells the cells apart: 0 for a line
/// element (or a vertex), 1 for a rigid tie (ParaView's Threshold on it shows either). Call
/// it once the grid's own cell arrays are complete.
void addTieCells(vtkUnstructuredGrid& grid, const Model& model);

/// Columns [first, first + 3) of a nodal field as a 3-component point array.
vtkSmartPointer<vtkDoubleArray> pointVectors(const char* name, const NodalField& field, int first);

/// Writes the grid as binary (zlib) VTK XML; throws std::runtime_error when VTK cannot.
void writeVtu(vtkUnstructuredGrid* grid, const std::filesystem::path& file);

}  // namespace beamrotor
