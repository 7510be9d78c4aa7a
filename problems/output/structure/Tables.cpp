// The CSV tables of one run (see Tables.hpp).
#include "problems/output/structure/Tables.hpp"

#include "problems/output/structure/Reactions.hpp"

#include <optional>

#include "fem/assembly/MemberExtrema.hpp"
#include "fem/assembly/Recovery.hpp"
#include "problems/output/structure/ModeShapes.hpp"

namespace beamrotor {

CsvTable staticFieldsTable(const std::string& title, const std::vector<StaticStation>& stations) {
  CsvTable table(title, {{"x", "m"},
                         {"ux", "m"},
                         {"uy", "m"},
                         {"uz", "m"},
                         {"rx", "rad"},
                         {"ry", "rad"},
                         {"rz", "rad"},
                         {"N", "N"},
                         {"Vy", "N"},
                         {"Vz", "N"},
                         {"T", "N m"},
                         {"My", "N m"},
                         {"Mz", "N m"},
                         {"stress", "Pa"},
                         {"shear", "Pa"},
                         {"stress_top", "Pa"},
                         {"stress_bottom", "Pa"},
                         {"shear_y", "Pa"},
                         {"shear_z", "Pa"},
                         {"element", ""}});
  table.reserveRows(stations.size());
  for (const StaticStation& st : stations) {
    const auto& u = st.displacement;
    const SectionForces& f = st.forces;
    table.addRow({st.place.x, u[0], u[1], u[2], u[3], u[4], u[5], f.N, f.Vy, f.Vz, f.T, f.My, f.Mz,
                  st.stress, st.shear, st.fibres.top, st.fibres.bottom, st.shearY, st.shearZ,
                  (long long)st.place.element});
  }
  return table;
}

namespace {

/// One row per component of `forces`, the first column named `whose`; the force (N) or moment
/// (N m) column left out when no component is of its kind and not `bothColumns` (a column
/// with no number at all reads as text in NumPy's genfromtxt).
CsvTable forceComponentsTable(const std::string& title, const Model& model,
                              const std::vector<ReactionComponent>& forces, const char* whose,
                              bool bothColumns) {
  bool anyForce = bothColumns, anyMoment = bothColumns;
  for (const ReactionComponent& f : forces) (isRotation(f.dof) ? anyMoment : anyForce) = true;
  std::vector<CsvColumn> columns{{whose, ""}, {"at", ""}, {"component", ""}};
  if (anyForce) columns.push_back({"force", "N"});
  if (anyMoment) columns.push_back({"moment", "N m"});
  CsvTable table(title, columns);
  for (const ReactionComponent& f : forces) {
    std::string at = model.nameOf(f.node);
    if (at.empty()) at = "node " + std::to_string(f.node);
    std::vector<CsvCell> row{f.support, at, std::string(reactionName(f.dof))};
    const bool moment = isRotation(f.dof);
    if (anyForce) row.push_back(moment ? CsvCell{std::monostate{}} : CsvCell{f.value});
    if (anyMoment) row.push_back(moment ? CsvCell{f.value} : CsvCell{std::monostate{}});
    table.addRow(std::move(row));
  }
  return table;
}

}  // namespace

CsvTable springForcesTable(const std::string& title, const Model& model,
                           const StaticResult& statics) {
  return forceComponentsTable(title, model, statics.elementForces, "spring", true);
}

CsvTable reactionsTable(const std::string& title, const Model& model, const StaticResult& statics) {
  return forceComponentsTable(title, model, statics.reactions, "support", false);
}

CsvTable modesTable(const std::string& title, const ModalResult& modal) {
  std::vector<CsvColumn> columns{{"mode", ""}, {"frequency", "Hz"}, {"description", ""}};
  for (int k = 0; k < 3; ++k)
    columns.push_back({"effective_mass_" + std::string(dofName(kAllDofs[k])), "kg"});
  for (int k = 0; k < 3; ++k)
    columns.push_back({"effective_mass_ratio_" + std::string(dofName(kAllDofs[k])), ""});
  for (Dof d : kAllDofs) columns.push_back({"energy_share_" + std::string(dofName(d)), ""});

  CsvTable table(title, columns);
  for (std::size_t m = 0; m < modal.modes.size(); ++m) {
    const Mode& mode = modal.modes[m];
    // Each cell made in place: moving a variant that may hold a string draws a false
    // -Wmaybe-uninitialized from GCC 12 in some unity batches.
    std::vector<CsvCell> row;
    row.emplace_back(std::in_place_type<long long>, (long long)(m + 1));
    row.emplace_back(std::in_place_type<double>, mode.frequencyHz);
    row.emplace_back(std::in_place_type<std::string>, mode.description);
    for (int k = 0; k < 3; ++k) row.push_back(mode.effectiveMass[k]);
    for (int k = 0; k < 3; ++k)
      row.push_back(modal.totalMass[k] > 0 ? mode.effectiveMass[k] / modal.totalMass[k] : 0.0);
    for (double share : mode.energyShare) row.push_back(share);
    table.addRow(std::move(row));
  }
  return table;
}

std::string modeShapeColumn(int mode, Dof dof) {
  return "mode" + std::to_string(mode) + "_" + std::string(dofName(dof));
}

namespace {

/// A frame's shapes: per member (its rows together, from its start) kIntervalsPerElement
/// pieces of each element, at the places' coordinates x, y, z, each mode's translations.
CsvTable frameShapesTable(const std::string& title, const Model& model, const ModalResult& modal) {
  std::vector<CsvColumn> columns{{"member", ""}, {"x", "m"}, {"y", "m"}, {"z", "m"}};
  std::vector<NodalField> shapes;
  for (std::size_t m = 0; m < modal.modes.size(); ++m) {
    shapes.push_back(displayModeShape(model, modal.modes[m].shape));
    for (int k = 0; k < 3; ++k) columns.push_back({modeShapeColumn(int(m) + 1, kAllDofs[k]), ""});
  }
  CsvTable table(title, columns);
  for (const auto& [name, elements] : model.members())
    for (std::size_t i = 0; i < elements.size(); ++i) {
      const auto& line = static_cast<const LineElement&>(*model.elements()[elements[i]]);
      for (int k = i == 0 ? 0 : 1; k <= kIntervalsPerElement; ++k) {
        const double s = double(k) / kIntervalsPerElement;
        const Eigen::Vector3d x = placeOnElement(model, elements[i], s);
        std::vector<CsvCell> row{name, x.x(), x.y(), x.z()};
        for (const NodalField& shape : shapes) {
          const auto u = displacementAlong(line, shape, s, SpanLoad::none);
          row.insert(row.end(), {u[0], u[1], u[2]});
        }
        table.addRow(std::move(row));
      }
    }
  return table;
}

}  // namespace

CsvTable modeShapesTable(const std::string& title, const Model& model, const ModalResult& modal) {
  if (!model.members().empty()) return frameShapesTable(title, model, modal);
  // Translations of every mode; a torsional mode also its rotation (largest 1), which is
  // what its chart draws.
  std::vector<CsvColumn> columns{{"x", "m"}};
  std::vector<NodalField> shapes;
  std::vector<std::optional<Dof>> rotations;
  for (std::size_t m = 0; m < modal.modes.size(); ++m) {
    shapes.push_back(displayModeShape(model, modal.modes[m].shape));
    for (int k = 0; k < 3; ++k) columns.push_back({modeShapeColumn(int(m) + 1, kAllDofs[k]), ""});
    const Dof charted = chartedDof(model, modal.modes[m].shape);
    rotations.push_back(isRotation(charted) ? std::optional<Dof>(charted) : std::nullopt);
    if (rotations.back()) columns.push_back({modeShapeColumn(int(m) + 1, charted), ""});
  }
  // The nodes hold the largest translation 1 (displayModeShape), but an element's cubic may
  // bulge past its nodes (1.02 on a coarse mesh): such a mode's samples are scaled so that the
  // largest drawn is 1 (its translations together, its charted rotation apart). A mode whose
  // samples stay within 1 is left as it is (a torsion mode's round-off translations too).
  std::vector<std::vector<double>> rows;
  for (const LinePlace& p : placesAlongLine(model, kIntervalsPerElement)) {
    const auto& line = static_cast<const LineElement&>(*model.elements()[p.element]);
    std::vector<double> row{p.x};
    for (std::size_t m = 0; m < shapes.size(); ++m) {
      const auto u = displacementAlong(line, shapes[m], p.s, SpanLoad::none);
      row.insert(row.end(), {u[0], u[1], u[2]});
      if (rotations[m]) row.push_back(u[dofIndex(*rotations[m])]);
    }
    rows.push_back(std::move(row));
  }
  std::size_t first = 1;  // the mode's first column
  for (std::size_t m = 0; m < shapes.size(); ++m) {
    const std::size_t width = rotations[m] ? 4 : 3;
    for (const auto& [from, to] : {std::pair<std::size_t, std::size_t>{first, first + 3},
                                   {first + 3, first + width}}) {
      double largest = 0;
      for (const auto& row : rows)
        for (std::size_t c = from; c < to; ++c) largest = std::max(largest, std::abs(row[c]));
      if (largest > 1)
        for (auto& row : rows)
          for (std::size_t c = from; c < to; ++c) row[c] /= largest;
    }
    first += width;
  }
  CsvTable table(title, columns);
  for (const auto& row : rows) table.addRow(std::vector<CsvCell>(row.begin(), row.end()));
  return table;
}

}  // namespace beamrotor
