// What the analyses with geometric stiffness write: a buckling analysis' load factors
// (results.json, <stem>_factors.csv), its mode shapes (<stem>_shapes.csv, one .vtu per mode
// with a .pvd, the chart <stem>_shapes.svg/png), and a second-order static analysis' critical
// factor and amplification (results.json, beside the usual static entries).
#pragma once

#include <filesystem>
#include <string>

#include "problems/deck/OutputUnits.hpp"
#include "problems/output/files/CsvTable.hpp"
#include "problems/output/JsonWriter.hpp"
#include "problems/output/PreparedRun.hpp"

namespace beamrotor {

/// One row per load factor: mode, load_factor, reversed (1 for the negative ones).
CsvTable bucklingFactorsTable(const std::string& title, const BucklingResult& r);

/// The buckling modes (positive factors, then the reversed ones) as modes for the shape
/// table, the VTK files and the chart; each description names its factor and, in a frame, the
/// rigid motion the shape mostly is (describeRigidMotion with a unit mass per translation:
/// "load factor 4.2, sway ux, 97 % of the motion").
ModalResult bucklingShapes(const Model& model, const BucklingResult& r);

/// results.json entry: {type, name, load_factors [...], reversed_load_factors [...], modes
/// [{mode, load_factor}], reference {reactions}, time_s, files}.
Json bucklingJson(const AnalysisOutcome& a);

/// The `second_order` object of a second-order static analysis' results.json entry:
/// {critical_factor, displacement_amplification, rotation_amplification,
/// moment_amplification, stress_amplification, iterations,
/// first_order {max_translation, max_rotation}}.
Json secondOrderJson(const SecondOrderResult& r);

/// Writes a buckling analysis' files into dir (charts when asked); p.modes holds its
/// bucklingFactorsTable, p.shapes the modeShapesTable of bucklingShapes.
/// A frame's chart is frameShapesChart (`planar`: a planar frame's); `units` are those the
/// tables are in.
void writeBucklingFiles(const PreparedAnalysis& p, const Model& model,
                        const std::filesystem::path& dir, const std::string& caption, bool charts,
                        bool planar, const OutputUnits& units = {});

}  // namespace beamrotor
