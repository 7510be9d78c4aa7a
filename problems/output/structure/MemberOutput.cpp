// Member output of a static analysis (see MemberOutput.hpp).
#include "problems/output/structure/MemberOutput.hpp"

#include <map>

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

CsvTable memberTable(const std::string& title, const Model& model,
                     const std::vector<int>& elements, const std::vector<StaticStation>& stations) {
  CsvTable table(title, {{"s", "m"},   {"x", "m"},    {"y", "m"},     {"z", "m"},
                         {"ux", "m"},  {"uy", "m"},   {"uz", "m"},    {"rx", "rad"},
                         {"ry", "rad"}, {"rz", "rad"}, {"N", "N"},    {"Vy", "N"},
                         {"Vz", "N"},  {"T", "N m"},  {"My", "N m"},  {"Mz", "N m"},
                         {"stress", "Pa"}, {"element", ""}, {"ey_x", ""}, {"ey_y", ""},
                         {"ey_z", ""},  {"ez_x", ""},  {"ez_y", ""},    {"ez_z", ""}});
  std::map<int, std::vector<const StaticStation*>> byElement;
  for (const StaticStation& st : stations) byElement[st.place.element].push_back(&st);
  double start = 0;
  for (int e : elements) {
    const LineElement& line = *asLine(model.elements().at(e));
    const double length = line.length();
    const Eigen::Matrix3d R = line.localAxes();
    for (const StaticStation* st : byElement[e]) {
      const Eigen::Vector3d x = placeOnElement(model, e, st->place.s);
      const auto& u = st->displacement;
      const SectionForces& f = st->forces;
      table.addRow({start + st->place.s * length, x.x(), x.y(), x.z(), u[0], u[1], u[2], u[3],
                    u[4], u[5], f.N, f.Vy, f.Vz, f.T, f.My, f.Mz, st->stress, (long long)e,
                    R(1, 0), R(1, 1), R(1, 2), R(2, 0), R(2, 1), R(2, 2)});
    }
    start += length;
  }
  return table;
}

std::string envelopeCsv(const std::string& stem, const std::string& member) {
  return stem + "_envelope_" + member + ".csv";
}

CsvTable memberEnvelopeTable(const std::string& title, const std::vector<EnvelopeStation>& stations,
                             const std::vector<std::string>& solutionNames) {
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
  CsvTable table(title, columns);
  for (const EnvelopeStation& st : stations) {
    // Sized first and filled in place: growing it, GCC 12 warns (wrongly) of a moved
    // variant's string as uninitialised in some unity batches.
    std::vector<CsvCell> row(2 + 4 * kForceComponents.size());
    row[0] = st.along;
    row[1] = (long long)st.element;
    for (std::size_t c = 0; c < kForceComponents.size(); ++c) {
      row[2 + 4 * c] = st.max[c];
      row[3 + 4 * c] = solutionNames.at(st.maxBy[c]);
      row[4 + 4 * c] = st.min[c];
      row[5 + 4 * c] = solutionNames.at(st.minBy[c]);
    }
    table.addRow(row);
  }
  return table;
}

Json membersJson(const Model& model, const NodalField& displacement, const std::string& stem) {
  Json out = Json::object();
  for (const auto& [name, elements] : model.members()) {
    double length = 0;
    for (int e : elements) length += asLine(model.elements().at(e))->length();
    const LineElement& first = *asLine(model.elements().at(elements.front()));
    const LineElement& last = *asLine(model.elements().at(elements.back()));
    Json m = {{"length", length},
              {"elements", elements.size()},
              {"from", model.nameOf(first.endNodes()[0])},
              {"to", model.nameOf(last.endNodes()[1])},
              {"csv", memberCsv(stem, name)}};
    const auto ranges = memberForceRanges(model, elements, displacement);
    for (std::size_t c = 0; c < kForceComponents.size(); ++c)
      m[componentName(kForceComponents[c])] = {{"max", valueJson(ranges[c].max)},
                                               {"min", valueJson(ranges[c].min)}};
    m["chord_deflection"] =
        valueJson(largestChordDeflection(model, elements, displacement));
    out[name] = m;
  }
  return out;
}

Json maxDisplacementJson(const Model& model, const NodalField& displacement) {
  const MemberValue top = largestDisplacement(model, displacement);
  return {{"value", top.value}, {"x", top.x.x()}, {"y", top.x.y()}, {"z", top.x.z()}};
}

}  // namespace beamrotor
