// VTK XML files for ParaView (and meshio): the model's line elements as VTK_LINE cells with
// point and cell data, and .pvd collections that let ParaView step through modes or sweep
// values as if they were time steps.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "fem/model/Model.hpp"
#include "fem/model/Results.hpp"
#include "fem/transient/TransientResults.hpp"
#include "problems/output/structure/LineSampling.hpp"

namespace beamrotor {

/// A static solution on the mesh. Points: every node of the model, point data `displacement`
/// (ux uy uz, m) and `rotation` (rx ry rz, rad), global frame. Cells: one VTK_LINE per line
/// element (other elements are not drawn), cell data `element` (index into model.elements()),
/// section forces `N`, `Vy`, `Vz` (N), `T`, `My`, `Mz` (N m) at the element's mid-length
/// (element frame; exact there, also with a span load), `stress` and `shear` (Pa, the largest
/// normal and transverse shear stress on the element, its `peaks`), the element's own end
/// rotations `rotation_start`, `rotation_end` (rx ry rz, rad; at a hinge they differ from the
/// node's; read from the end `stations`) and section properties `A` (m^2), `Iy`, `Iz` (m^4), `E`
/// (Pa). Point data also `reaction_force` (N) and `reaction_moment` (N m), the supports'
/// reactions at their nodes, and `spring_force`, `spring_moment`, the forces springs and
/// bearings exert at their `at` nodes (`statics`' reactions and elementForces; zero elsewhere;
/// ParaView's Glyph draws them as arrows). Throws std::runtime_error when VTK cannot write the
/// file.
void writeStaticVtu(const std::filesystem::path& file, const LoadedSolution& solution,
                    const StaticResult& statics, const std::vector<StaticStation>& stations,
                    const std::vector<ElementPeaks>& peaks);

/// One mode on the mesh: point data `mode_shape` (translations scaled by displayModeShape,
/// largest 1) and `mode_rotation` (rotations, same scale), cell data `element` and section
/// properties, field data `mode` (1-based number) and `frequency_hz`.
void writeModeVtu(const std::filesystem::path& file, const Model& model, const Mode& mode,
                  int number);
/// The same for any shape (display-scaled as a mode) numbered `number`, with one value of the
/// mode in the field data under `valueName` (e.g. "load_factor" for a buckling mode).
void writeShapeVtu(const std::filesystem::path& file, const Model& model, const NodalField& shape,
                   int number, const std::string& valueName, double value);

/// One frame of a transient run: the line elements as VTK_LINE cells, or, for a model
/// without them (bodies on springs), one VTK_VERTEX per node; point data `displacement`
/// (ux uy uz, m) and `rotation` (rx ry rz, rad), field data `time` (s).
void writeFrameVtu(const std::filesystem::path& file, const Model& model, const Frame& frame);

/// One data set of a collection: the file (relative to the .pvd) shown at `timestep`.
struct PvdEntry {
  double timestep = 0;
  std::string file;
};

/// A ParaView collection file (<VTKFile type="Collection">) listing the entries in order.
void writePvd(const std::filesystem::path& file, const std::vector<PvdEntry>& entries);

}  // namespace beamrotor
