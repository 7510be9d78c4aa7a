// Member output of a static analysis (see MemberOutput.hpp).
#include "problems/output/structure/MemberOutput.hpp"


#include "fem/assembly/MemberExtrema.hpp"

namespace beamrotor {

namespace {

Json valueJson(const MemberValue& v) {
  return {{"value", v.value}, {"s", v.along}, {"x", v.x.x()}, {"y", v.x.y()}, {"z", v.x.z()},
          {"element", v.element}};
}

}  // namespace

std::string memberCsv(const std::string& stem, const std::string& member) {
  return stem + "_member_" + member + ".csv";
}

std::string membersCsv(const std::string& stem) {
  return stem + "_members.csv";
}

bool oneMembersTable(const Model& model) {
  return model.members().size() > kMemberFilesUpTo;
}

std::string memberCsvOf(const Model& model, const std::string& stem, const std::string& member) {
  return oneMembersTable(model) ? membersCsv(stem) : memberCsv(stem, member);
}

namespace {

/// The member table's columns, after `member` when the table holds every member.
std::vector<CsvColumn> memberColumns(bool named) {
  std::vector<CsvColumn> columns{
      {"s", "m"},     {"x", "m"},    {"y", "m"},    {"z", "m"},     {"ux", "m"},
      {"uy", "m"},    {"uz", "m"},   {"rx", "rad"}, {"ry", "rad"},  {"rz", "rad"},
      {"N", "N"},     {"Vy", "N"},   {"Vz", "N"},   {"T", "N m"},   {"My", "N m"},
      {"Mz", "N m"},  {"stress", "Pa"}, {"element", ""}, {"ey_x", ""}, {"ey_y", ""},
      {"ey_z", ""},   {"ez_x", ""},  {"ez_y", ""},  {"ez_z", ""}};
  if (named) columns.insert(columns.begin(), {"member", ""});
  return columns;
}

/// The rows of one member (its elements' stations from its start), `name` first when given.
void addMemberRows(CsvTable& table, const Model& model, const std::vector<int>& elements,
                   const StationsByElement& stations, const std::string* name) {
  double start = 0;
  std::vector<CsvCell> row;  // one row's cells, reused
  row.reserve(25);
  for (int e : elements) {
    const LineElement& line = *asLine(model.elements().at(e));
    const double length = line.length();
    const Eigen::Matrix3d R = line.localAxes();
    for (const StaticStation& st : stations.of(e)) {
      const Eigen::Vector3d x = placeOnElement(model, e, st.place.s);
      const auto& u = st.displacement;
      const SectionForces& f = st.forces;
      row.clear();
      if (name) row.emplace_back(std::in_place_type<std::string>, *name);
      for (double v : {start + st.place.s * length, x.x(), x.y(), x.z(), u[0], u[1], u[2], u[3],
                       u[4], u[5], f.N, f.Vy, f.Vz, f.T, f.My, f.Mz, st.stress})
        row.emplace_back(std::in_place_type<double>, v);
      row.emplace_back(std::in_place_type<long long>, e);
      for (double v : {R(1, 0), R(1, 1), R(1, 2), R(2, 0), R(2, 1), R(2, 2)})
        row.emplace_back(std::in_place_type<double>, v);
      table.addRow(row);
    }
    start += length;
  }
}

}  // namespace

CsvTable memberTable(const std::string& title, const Model& model,
                     const std::vector<int>& elements, const StationsByElement& stations) {
  CsvTable table(title, memberColumns(false));
  std::size_t rows = 0;
  for (int e : elements) rows += stations.of(e).size();
  table.reserveRows(rows);
  addMemberRows(table, model, elements, stations, nullptr);
  return table;
}

CsvTable membersTable(const std::string& title, const Model& model,
                      const StationsByElement& stations) {
  CsvTable table(title, memberColumns(true));
  std::size_t rows = 0;
  for (const auto& [name, elements] : model.members())
    for (int e : elements) rows += stations.of(e).size();
  table.reserveRows(rows);
  for (const auto& [name, elements] : model.members())
    addMemberRows(table, model, elements, stations, &name);
  return table;
}

std::string envelopeCsv(const std::string& stem, const std::string& member) {
  return stem + "_envelope_" + member + ".csv";
}

std::string envelopesCsv(const std::string& stem) {
  return stem + "_envelopes.csv";
}

std::string envelopeCsvOf(const Model& model, const std::string& stem, const std::string& member) {
  return oneMembersTable(model) ? envelopesCsv(stem) : envelopeCsv(stem, member);
}

bool caseMemberDetail(const Model& model, std::size_t cases) {
  return model.members().size() * cases <= kCaseMemberEntries;
}

bool caseChordDeflections(const Model& model, std::size_t cases) {
  return caseMemberDetail(model, cases) || cases <= kSummaryCases;
}

namespace {

/// The envelope table's columns, after `member` when the table holds every member.
std::vector<CsvColumn> envelopeColumns(bool named) {
  std::vector<CsvColumn> columns{{"s", "m"}, {"element", ""}};
  for (ForceComponent c : kForceComponents) {
    const std::string name = componentName(c);
    const std::string unit = (c == ForceComponent::N || c == ForceComponent::Vy ||
                              c == ForceComponent::Vz) ? "N" : "N m";
    columns.push_back({name + "_max", unit});
    columns.push_back({name + "_max_case", ""});
    columns.push_back({name + "_min", unit});
    columns.push_back({name + "_min_case", ""});
  }
  if (named) columns.insert(columns.begin(), {"member", ""});
  return columns;
}

/// The rows of one member's envelope, `name` first when given.
void addEnvelopeRows(CsvTable& table, const std::vector<EnvelopeStation>& stations,
                     const std::vector<std::string>& solutionNames, const std::string* name) {
  std::vector<CsvCell> row;  // one row's cells, reused
  for (const EnvelopeStation& st : stations) {
    row.clear();
    if (name) row.emplace_back(std::in_place_type<std::string>, *name);
    row.emplace_back(std::in_place_type<double>, st.along);
    row.emplace_back(std::in_place_type<long long>, st.element);
    // Each cell made in place: moving a variant that may hold a string draws a false
    // -Wmaybe-uninitialized from GCC 12 in some unity batches.
    for (std::size_t c = 0; c < kForceComponents.size(); ++c) {
      row.emplace_back(std::in_place_type<double>, st.max[c]);
      row.emplace_back(std::in_place_type<std::string>, solutionNames.at(st.maxBy[c]));
      row.emplace_back(std::in_place_type<double>, st.min[c]);
      row.emplace_back(std::in_place_type<std::string>, solutionNames.at(st.minBy[c]));
    }
    table.addRow(row);
  }
}

}  // namespace

CsvTable memberEnvelopeTable(const std::string& title, const std::vector<EnvelopeStation>& stations,
                             const std::vector<std::string>& solutionNames) {
  CsvTable table(title, envelopeColumns(false));
  addEnvelopeRows(table, stations, solutionNames, nullptr);
  return table;
}

CsvTable membersEnvelopeTable(const std::string& title, const Model& model,
                              const std::vector<std::vector<EnvelopeStation>>& stations,
                              const std::vector<std::string>& solutionNames) {
  CsvTable table(title, envelopeColumns(true));
  for (std::size_t m = 0; m < model.members().size(); ++m)
    addEnvelopeRows(table, stations.at(m), solutionNames, &model.members()[m].first);
  return table;
}

Json membersJson(const Model& model, const StaticExtremes& extremes, const std::string& stem) {
  Json out = objectWithRoom(model.members().size());
  for (std::size_t i = 0; i < model.members().size(); ++i) {
    const auto& [name, elements] = model.members()[i];
    double length = 0;
    for (int e : elements) length += asLine(model.elements().at(e))->length();
    const LineElement& first = *asLine(model.elements().at(elements.front()));
    const LineElement& last = *asLine(model.elements().at(elements.back()));
    Json m = {{"length", length},
              {"elements", elements.size()},
              {"from", model.nameOf(first.endNodes()[0])},
              {"to", model.nameOf(last.endNodes()[1])},
              {"csv", memberCsvOf(model, stem, name)}};
    const auto& ranges = extremes.ranges.at(i);
    for (std::size_t c = 0; c < kForceComponents.size(); ++c)
      m[componentName(kForceComponents[c])] = {{"max", valueJson(ranges[c].max)},
                                               {"min", valueJson(ranges[c].min)}};
    m["chord_deflection"] = valueJson(extremes.chordDeflections.at(i));
    appendNew(out, name, std::move(m));
  }
  return out;
}

Json maxDisplacementJson(const MemberValue& top) {
  return {{"value", top.value}, {"x", top.x.x()}, {"y", top.x.y()}, {"z", top.x.z()}};
}

}  // namespace beamrotor
