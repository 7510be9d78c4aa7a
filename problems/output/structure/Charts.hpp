// The charts a person would rather look at than read, as gnuplot scripts over the CSV
// tables: the diagrams of a static solution along the line (deflection, rotation, bending
// moment, stress, stacked like the published figures of the pump rod), the first mode
// shapes, sweep quantities against the swept parameter, and transient histories in time.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "fem/model/Model.hpp"
#include "fem/model/Results.hpp"
#include "problems/deck/OutputUnits.hpp"
#include "problems/output/files/CsvTable.hpp"
#include "problems/output/files/Gnuplot.hpp"
#include "problems/output/SweepTable.hpp"

namespace beamrotor {

/// A named point of the model on the line: drawn as a dashed vertical line with its name.
struct ChartMarker {
  std::string name;
  double x = 0;  ///< distance along the line (m), see lineCoordinates
};

/// The named points that lie on line elements, in order along the line.
std::vector<ChartMarker> namedPointMarkers(const Model& model);

/// The named points at the same place in every model (a point that moves from one model to
/// the next would need a marker per model), as namedPointMarkers of the first.
std::vector<ChartMarker> commonPointMarkers(const std::vector<const Model*>& models);

/// The diagrams along a line, top to bottom as staticDiagrams stacks them; each named by the
/// word `beamrotor overlay --quantity` takes.
/// `force` is the shear force, `shear` the shear stress.
enum class Diagram { deflection, rotation, moment, stress, shear, force };
inline const std::vector<Diagram> kAllDiagrams{Diagram::deflection, Diagram::rotation,
                                               Diagram::moment,     Diagram::force,
                                               Diagram::stress,     Diagram::shear};
std::string_view diagramName(Diagram d);

/// One static solution on the diagrams: its staticFieldsTable, the CSV file it was written
/// to (relative to the chart's directory) and its key title (ignored for a single series).
struct FieldSeries {
  const CsvTable* fields = nullptr;
  std::string csvFile;
  std::string title;  ///< e.g. "eta = 0.2"
};

/// Stacked diagrams along the line (those in `shown`), in the user's `units` where set (the
/// tables hold them), else: deflection uy (mm), rotation rz (mrad),
/// bending moment Mz (kN m), shear force Vy (kN), normal stress at the top and bottom fibre and shear stress of Vy,
/// signed (MPa); uz, ry, My, Vz and the shear of Vz are added when they are not zero everywhere
/// (3D models). Several series (the values of a short
/// sweep) are overlaid, one line each, like the published figures of the pump rod.
ChartScript staticDiagrams(const std::string& caption, const std::string& chartName,
                           const std::vector<FieldSeries>& series,
                           const std::vector<ChartMarker>& markers,
                           const std::vector<Diagram>& shown = kAllDiagrams,
                           const OutputUnits& units = {});

/// Mode shapes from a modeShapesTable written to csvFile, each drawn by its dominant
/// translation (largest value 1) and keyed "mode N: label N"; at most labels.size() of them.
ChartScript labelledShapesChart(const std::string& caption, const std::string& chartName,
                                const Model& model, const std::vector<Mode>& modes,
                                const std::vector<std::string>& labels, const CsvTable& shapes,
                                const std::string& csvFile, const OutputUnits& units = {});

/// The first `count` mode shapes (each its dominant translation, largest value 1) from a
/// modeShapesTable written to csvFile.
ChartScript modeShapesChart(const std::string& caption, const std::string& chartName,
                            const Model& model, const ModalResult& modal, const CsvTable& shapes,
                            const std::string& csvFile, const OutputUnits& units = {},
                            int count = 4);

/// One panel per reaction component and the largest normal and shear stress of a static
/// analysis, per maximum of a transient one, or the frequencies of a modal one, against the
/// swept parameter (labelled with its SI unit when the deck gave one, `unit`), from sweepTable
/// in csvFile.
/// `quantities` are those of this analysis.
ChartScript sweepChart(const std::string& caption, const std::string& chartName,
                       const std::string& parameter, const std::string& unit,
                       const std::vector<SweepQuantity>& quantities,
                       const CsvTable& table, const std::string& csvFile,
                       const OutputUnits& units = {});

/// One panel per column of a transient history table (after its first column, time t in s)
/// against time, from historyTable written to csvFile.
ChartScript historyChart(const std::string& caption, const std::string& chartName,
                         const CsvTable& table, const std::string& csvFile);

}  // namespace beamrotor
