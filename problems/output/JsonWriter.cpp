// results.json and sweep.json (layout in JsonWriter.hpp), and results.json written a case at
// a time (ResultsDocument.hpp).
#include "problems/output/JsonWriter.hpp"
#include "problems/output/ResultsDocument.hpp"

#include <algorithm>
#include <map>
#include <memory>
#include <set>
#include <cmath>
#include <stdexcept>
#include <string_view>

#include "fem/assembly/MemberExtrema.hpp"
#include "fem/model/DofMap.hpp"
#include "problems/deck/AnalysisKinds.hpp"
#include "problems/deck/ShownFieldUnit.hpp"
#include "problems/output/structure/MemberEndRotations.hpp"
#include "problems/output/structure/AdequateJson.hpp"
#include "problems/output/structure/CaseEnvelope.hpp"
#include "problems/output/crank/CrankOutput.hpp"
#include "problems/output/moving/MovingOutput.hpp"
#include "problems/output/torsion/TorsionOutput.hpp"
#include "problems/output/files/CsvTable.hpp"
#include "problems/output/files/FileNames.hpp"
#include "problems/output/files/FileWriting.hpp"
#include "problems/output/files/Interruption.hpp"
#include "problems/output/structure/MemberOutput.hpp"
#include "problems/output/structure/Reactions.hpp"
#include "problems/output/rotor/RotorJson.hpp"
#include "problems/output/structure/StabilityOutput.hpp"
#include "problems/output/transient/TransientJson.hpp"
#include "problems/run/Overloaded.hpp"
#include "problems/output/structure/BaseMotionOutput.hpp"
#include "problems/output/structure/SpectrumOutput.hpp"

namespace beamrotor {

Json objectWithRoom(std::size_t entries) {
  Json out = Json::object();
  out.get_ref<Json::object_t&>().reserve(entries);
  return out;
}

Json& appendNew(Json& object, std::string key, Json value) {
  auto& entries = object.get_ref<Json::object_t&>();
  using Entries = std::vector<Json::object_t::value_type>;
  static_cast<Entries&>(entries).emplace_back(std::move(key), std::move(value));
  return entries.back().second;
}

namespace {

/// The dof kinds some node of the model carries.
std::array<bool, kDofKinds> kindsCarried(const Model& model, const DofMap& dofs) {
  std::array<bool, kDofKinds> carried{};
  for (int n = 0; n < model.nodeCount(); ++n)
    for (Dof d : kAllDofs) carried[dofIndex(d)] = carried[dofIndex(d)] || dofs.equation(n, d) >= 0;
  return carried;
}

Json modelJson(const RunResult& run, const DofMap& dofs) {
  return {{"nodes", run.model->nodeCount()},
          {"elements", run.model->elements().size()},
          {"dofs", dofs.size()},
          {"dimension", run.dimension}};
}

/// Displacements of the named points, in node order (the order along a line): point(name) for
/// each point, then component(key, value) for each of its components. At a hinge each
/// rotation the model carries is also given per side, "rz_left" and "rz_right" (the beam ends'
/// own), and the node's value only where the node carries it. In a frame, where several
/// members may meet, per member end instead: "rz_<member>_start", "rz_<member>_end" (or
/// _before and _after where the joint lies inside the member; memberEndRotations).
template <class Point, class Component>
void forEachPointDisplacement(const Model& model, const DofMap& dofs,
                              const std::array<bool, kDofKinds>& carried, const StaticResult& r,
                              const Point& point, const Component& component) {
  std::vector<std::pair<int, std::string>> points;
  for (const auto& [name, node] : model.namedNodes()) points.emplace_back(node, name);
  std::sort(points.begin(), points.end());
  const bool frame = !model.members().empty();
  std::map<int, std::vector<MemberEndRotation>> ends;
  if (frame && !r.hinges.empty()) ends = memberEndRotations({model, r.displacement}, r.hinges);
  for (const auto& [node, name] : points) {
    point(name);
    for (Dof d : kAllDofs)
      if (dofs.equation(node, d) >= 0)
        component(std::string(dofName(d)), r.displacement(node, dofIndex(d)));
    if (const auto at = ends.find(node); at != ends.end())
      for (Dof d : kAllDofs)
        if (isRotation(d) && carried[dofIndex(d)])
          for (const MemberEndRotation& e : at->second)
            component(std::string(dofName(d)) + "_" + e.label, e.rotation[dofIndex(d) - 3]);
    for (const SideRotations& h : r.hinges) {
      if (frame || h.node != node) continue;
      for (Dof d : kAllDofs)
        if (isRotation(d) && carried[dofIndex(d)])
          for (const auto& [side, value] :
               {std::pair{"_left", &h.left}, std::pair{"_right", &h.right}})
            if (*value) component(std::string(dofName(d)) + side, (**value)[dofIndex(d) - 3]);
    }
  }
}

/// {point: {ux ... rz ...}}: forEachPointDisplacement's values.
Json pointDisplacementsJson(const Model& model, const DofMap& dofs,
                            const std::array<bool, kDofKinds>& carried, const StaticResult& r) {
  Json out = objectWithRoom(model.namedNodes().size());
  Json* components = nullptr;  // stays in place: out has room for every point
  forEachPointDisplacement(
      model, dofs, carried, r, [&](const std::string& name) { components = &appendNew(out, name); },
      [&](const std::string& key, double value) { (*components)[key] = value; });
  return out;
}

/// Contact constraints by name: whether each rests on its bound, and the force it exerts.
Json contactsJson(const std::vector<ContactState>& contacts) {
  Json out = Json::object();
  for (const ContactState& c : contacts)
    out[c.name] = {{"dof", std::string(dofName(c.dof))},
                   {"active", c.active},
                   {"value", c.value},
                   {"bound", c.bound},
                   {"gap", c.gap},
                   {"force", c.force}};
  return out;
}

/// Tension-only and compression-only members by name: whether each is slack, its axial force
/// and the change of its length.
Json oneWayMembersJson(const std::vector<OneWayMemberState>& members) {
  Json out = Json::object();
  for (const OneWayMemberState& m : members)
    out[m.name] = {{"slack", m.slack}, {"force", m.force}, {"elongation", m.elongation}};
  return out;
}

/// A largest stress: value (Pa), place along the line, element and its section.
Json peakJson(const Model& model, const std::optional<LinePeak>& top) {
  if (!top) return nullptr;  // no line elements: the key is dropped by the caller
  const LineElement& line = *asLine(model.elements()[top->place.element]);
  Json out = {{"value", top->value},
              {"x", top->place.x},
              {"element", top->place.element},
              {"section", line.section().name}};
  // In a frame, also the member and the place in space (x above is along the elements' chain).
  if (const auto member = memberLocation(model, top->place.element, top->place.s)) {
    const Eigen::Vector3d at = placeOnElement(model, top->place.element, top->place.s);
    out["member"] = model.members()[member->first].first;
    out["s"] = member->second;
    out["point"] = {at.x(), at.y(), at.z()};
  }
  return out;
}

/// The largest normal and shear stress of a solution, under `max_stress` and `max_shear`.
void stressPeaksJson(Json& out, const Model& model, const std::vector<ElementPeaks>& peaks) {
  for (const auto& [key, kind] : {std::pair{"max_stress", &ElementPeaks::stress},
                                  std::pair{"max_shear", &ElementPeaks::shear}})
    if (Json top = peakJson(model, largestAlongLine(model, peaks, kind)); !top.is_null())
      out[key] = top;
}

/// One load case or combination: its factors (a combination), reactions, point displacements,
/// largest stresses, member extremes and warnings.
Json caseJson(const Model& model, const DofMap& dofs, const std::array<bool, kDofKinds>& carried,
              const CaseOutcome& c, const StaticExtremes& extremes, const std::string& stem,
              bool memberDetail) {
  Json out = objectWithRoom(16);
  out["name"] = c.name;
  out["combination"] = c.combination;
  if (c.combination) {
    Json factors = Json::object();
    for (const auto& [name, factor] : c.factors) factors[name] = factor;
    out["factors"] = factors;
  }
  out["reactions"] = reactionsJson(c.statics);
  if (!c.statics.elementForces.empty()) out["springs"] = forcesJson(c.statics.elementForces);
  out["displacements"] = pointDisplacementsJson(model, dofs, carried, c.statics);
  stressPeaksJson(out, model, extremes.peaks);
  if (!model.members().empty()) out["max_displacement"] = maxDisplacementJson(extremes.largestDisplacement);
  if (memberDetail) {
    Json members = membersJson(model, extremes, stem);
    for (auto& item : members.items()) item.value().erase("csv");  // written for the analysis only
    out["members"] = std::move(members);
  }
  out["warnings"] = c.warnings;
  return out;
}

/// Keeps the larger (or smaller) of value and the bound's, with the case that gave it.
void widen(Json& bound, double value, const std::string& name, bool larger) {
  if (bound.is_null() || (larger ? value > bound.at("value").get<double>()
                                 : value < bound.at("value").get<double>()))
    bound = {{"value", value}, {"case", name}};
}

/// {value, case}: a governed value and its combination's name.
Json governedJson(const Governed& g, const std::vector<CaseOutcome>& cases) {
  return {{"value", g.value}, {"case", cases.at(g.by).name}};
}

/// The envelope over the combinations: for each point displacement component (the cases' own,
/// forEachPointDisplacement), each reaction component and each spring's or bearing's force its
/// max and min, for each member resultant the max of its maxima and the min of its minima along
/// the member, the largest displacement and normal stress; each with the combination that
/// gives it.
Json envelopeJson(const Model& model, const DofMap& dofs,
                  const std::array<bool, kDofKinds>& carried,
                  const std::vector<CaseOutcome>& cases, const CaseEnvelope& envelope) {
  Json out = {{"reactions", Json::object()}, {"displacements", Json::object()},
              {"members", Json::object()}};
  out["members"].get_ref<Json::object_t&>().reserve(envelope.members.size());
  const auto forces = [&](const char* key, const auto& list) {
    for (const auto& [r, range] : list)
      out[key][r.support][std::string(reactionName(r.dof))] = {
          {"max", governedJson(range.max, cases)}, {"min", governedJson(range.min, cases)}};
  };
  forces("reactions", envelope.reactions);
  if (!envelope.springs.empty()) forces("springs", envelope.springs);
  // Every combination lists the same points and components in the same order (the model's):
  // the first builds the entries, the others find theirs by position (a key looked up in an
  // object is a linear search), checked against the key, by name if it differs.
  struct Slot {
    const std::string* point;
    const std::string* component;
    Json* entry;
  };
  std::vector<Slot> slots;
  bool built = false, byPosition = true;
  for (const CaseOutcome& c : cases) {
    if (!c.combination) continue;
    std::size_t i = 0;
    const std::string* point = nullptr;
    forEachPointDisplacement(
        model, dofs, carried, c.statics, [&](const std::string& name) { point = &name; },
        [&](const std::string& component, double value) {
          Json* e = nullptr;
          if (built && byPosition && i < slots.size() && *slots[i].point == *point &&
              *slots[i].component == component)
            e = slots[i].entry;
          else {
            byPosition = !built;  // a new key may move the entries held: by name from here on
            e = &out["displacements"][*point][component];
          }
          ++i;
          widen((*e)["max"], value, c.name, true);
          widen((*e)["min"], value, c.name, false);
        });
    if (built) continue;
    built = true;
    Json& points = out["displacements"];
    for (auto point = points.begin(); point != points.end(); ++point)
      for (auto component = point->begin(); component != point->end(); ++component)
        slots.push_back({&point.key(), &component.key(), &component.value()});
  }
  for (std::size_t m = 0; m < envelope.members.size(); ++m) {
    Json& member = appendNew(out["members"], model.members()[m].first);
    for (std::size_t f = 0; f < kForceComponents.size(); ++f)
      member[componentName(kForceComponents[f])] = {
          {"max", governedJson(envelope.members[m][f].max, cases)},
          {"min", governedJson(envelope.members[m][f].min, cases)}};
  }
  if (envelope.largestDisplacement.by >= 0)
    out["max_displacement"] = governedJson(envelope.largestDisplacement, cases);
  if (envelope.largestStress.by >= 0)
    out["max_stress"] = governedJson(envelope.largestStress, cases);
  return out;
}

/// A static analysis' entry; its load cases' entries are left to `entries` (an empty "cases").
Json staticJson(const Model& model, const std::shared_ptr<const DofMap>& dofMap,
                const std::array<bool, kDofKinds>& carried, const AnalysisOutcome& a,
                const AnalysisExtremes& extremes, std::vector<CaseEntries>& entries,
                std::size_t analysis) {
  const DofMap& dofs = *dofMap;
  const StaticExtremes& own = extremes.own.value();
  const StaticResult& r = *staticsOf(a);
  const std::string stem = fileStem(a.name);
  Json out = objectWithRoom(32);
  out["type"] = a.type;
  out["name"] = a.name;
  out["reactions"] = reactionsJson(r);
  if (!r.elementForces.empty()) out["springs"] = forcesJson(r.elementForces);
  out["displacements"] = pointDisplacementsJson(model, dofs, carried, r);
  if (!model.members().empty()) {
    out["max_displacement"] = maxDisplacementJson(own.largestDisplacement);
    out["members"] = membersJson(model, own, stem);
  }
  stressPeaksJson(out, model, own.peaks);
  if (!r.contacts.empty()) {
    out["contacts"] = contactsJson(r.contacts);
    out["active_set_iterations"] = r.activeSetIterations;
  }
  if (!r.oneWayMembers.empty()) out["one_way_members"] = oneWayMembersJson(r.oneWayMembers);
  out["rcond"] = r.rcond;
  out["round_off"] = r.roundOff;
  out["solver"] = r.solver;
  out["time_s"] = r.time.total;
  if (const auto* s = resultOf<StaticOutcome>(a); s && !s->ownLoads) out["loaded"] = false;
  out["files"] = {{"fields_csv", fieldsCsv(stem)}, {"vtu", staticVtu(stem)}};
  if (!casesOf(a).empty()) {
    out["cases"] = Json::array();
    entries.emplace_back(model, dofMap, carried, a, extremes, analysis);
    out["files"]["cases_csv"] = casesCsv(stem);
    out["files"]["cases_pvd"] = casesPvd(stem);
    if (std::any_of(casesOf(a).begin(), casesOf(a).end(),
                    [](const CaseOutcome& c) { return c.combination; })) {
      out["envelope"] = envelopeJson(model, dofs, carried, casesOf(a),
                                     caseEnvelope(model, casesOf(a), extremes.cases, extremes.canGovern));
      if (!model.members().empty()) {
        Json files = Json::object();
        for (const auto& [name, elements] : model.members())
          appendNew(files, name, envelopeCsvOf(model, stem, name));
        out["files"]["envelope_csv"] = files;
      }
    }
  }
  return out;
}

Json modalJson(const std::array<bool, kDofKinds>& carried, const AnalysisOutcome& a,
               const ModalResult& r) {
  const std::string stem = fileStem(a.name);
  // Per translation kind the model carries: value(k) for k = 0 (ux), 1 (uy), 2 (uz).
  const auto perTranslation = [&](auto value) {
    Json o = Json::object();
    for (int k = 0; k < 3; ++k)
      if (carried[k]) o[std::string(dofName(kAllDofs[k]))] = value(k);
    return o;
  };
  Json out = {{"type", a.type}, {"name", a.name}};
  Json frequencies = Json::array(), modes = Json::array(), vtus = Json::array();
  for (std::size_t m = 0; m < r.modes.size(); ++m) {
    const Mode& mode = r.modes[m];
    frequencies.push_back(mode.frequencyHz);
    Json energy = Json::object();
    for (Dof d : kAllDofs)
      if (carried[dofIndex(d)]) energy[std::string(dofName(d))] = mode.energyShare[dofIndex(d)];
    modes.push_back(
        {{"mode", m + 1},
         {"frequency_hz", mode.frequencyHz},
         {"rigid_body", mode.rigidBody},
         {"description", mode.description},
         {"effective_mass_kg", perTranslation([&](int k) { return mode.effectiveMass[k]; })},
         // A direction in which nothing moves (all its dofs held) has no mass: ratio 0.
         {"effective_mass_ratio", perTranslation([&](int k) {
            return r.totalMass[k] > 0 ? mode.effectiveMass[k] / r.totalMass[k] : 0.0;
          })},
         {"energy_share", energy}});
    vtus.push_back(modeVtu(stem, int(m) + 1));
  }
  out["frequencies_hz"] = frequencies;
  out["total_mass_kg"] = perTranslation([&](int k) { return r.totalMass[k]; });
  out["modes"] = modes;
  out["time_s"] = r.time.total;
  out["files"] = {{"modes_csv", modesCsv(stem)},
                  {"shapes_csv", shapesCsv(stem)},
                  {"pvd", collectionPvd(stem)},
                  {"vtu", vtus}};
  return out;
}

Json checksJson(const std::vector<Check>& checks) {
  Json out = Json::array();
  for (const Check& c : checks) {
    Json row = {{"name", c.name},
                {"quantity", c.quantity},
                {"computed", c.computed},
                {"reference", c.reference},
                {"unit", bareUnitName(checkQuantityUnit(c.quantity))},
                {"rel_error", c.relError()},
                {"tolerance", c.tolerance},
                {"pass", c.pass()}};
    if (c.paper) {
      row["paper"] = *c.paper;
      row["paper_rel_difference"] = std::abs(c.computed - *c.paper) / std::abs(*c.paper);
      row["reason"] = c.reason;
    }
    out.push_back(std::move(row));
  }
  return out;
}

Json parametersJson(const std::vector<std::pair<std::string, double>>& parameters) {
  Json out = Json::object();
  for (const auto& [name, value] : parameters) out[name] = value;
  return out;
}

/// A JSON pointer token: '~' and '/' escaped as RFC 6901 asks.
std::string pointerToken(const std::string& key) {
  std::string out;
  for (char c : key) out += c == '~' ? "~0" : c == '/' ? "~1" : std::string(1, c);
  return out;
}

void requireFiniteAt(const Json& node, const std::string& path, const std::string& document) {
  if (node.is_number_float() && !std::isfinite(node.get<double>()))
    throw std::runtime_error(document + ": " + (path.empty() ? "/" : path) + " would be " +
                             exactDecimal(node.get<double>()) +
                             "; only finite numbers are written");
  if (node.is_object())
    for (const auto& [key, child] : node.items())
      requireFiniteAt(child, path + "/" + pointerToken(key), document);
  if (node.is_array())
    for (std::size_t i = 0; i < node.size(); ++i)
      requireFiniteAt(node[i], path + "/" + std::to_string(i), document);
}

/// The part of a run's analysis entry a sweep tracks.
Json sweepAnalysisJson(const Json& analysis) {
  Json out = {{"type", analysis.at("type")}, {"name", analysis.at("name")}};
  for (const char* key : {"reactions", "max_stress", "max_shear", "frequencies_hz", "maxima",
                          "second_order", "load_factors", "critical_speeds", "instability_onset",
                          "smallest_log_decrement"})
    if (analysis.contains(key) &&
        !(analysis.at("type") == analysisTypeName<FrequencyResponseSpec>() &&
          std::string_view(key) == "frequencies_hz"))
      out[key] = analysis[key];
  // An unbalance analysis: each response point's peak and the API 684 verdict, not the curves.
  if (analysis.contains("response")) {
    Json peaks = Json::object();
    for (const auto& [point, response] : analysis["response"].items())
      peaks[point] = response.at("peak");
    out["peaks"] = peaks;
    const Json& api = analysis.value("api684", Json(nullptr));
    if (!api.is_null()) out["api684_pass"] = api.at("pass");
  }
  return out;
}

/// Per static analysis, its largest stress and shear over the sweep's runs (the first run on
/// ties), each with the swept parameter's value there.
Json sweepWorstJson(const SweepResult& sweep, const std::vector<Json>& runDocs) {
  Json out = Json::object();
  for (std::size_t i = 0; i < runDocs.size(); ++i)
    for (const Json& a : runDocs[i].at("analyses"))
      for (const char* key : {"max_stress", "max_shear"}) {
        if (!a.contains(key)) continue;
        Json& worst = out[a.at("name").get<std::string>()][key];
        if (!worst.is_null() && worst.at("value") >= a[key].at("value")) continue;
        worst = a[key];
        worst["at"] = {{sweep.parameter, sweep.values[i]}};
      }
  return out;
}

}  // namespace

Json reactionsJson(const StaticResult& r) {
  return forcesJson(r.reactions);
}

Json forcesJson(const std::vector<ReactionComponent>& forces) {
  Json out = Json::object();
  for (const SupportReactions& s : forcesByName(forces)) {
    Json& components = appendNew(out, s.support);
    for (const auto& [dof, value] : s.components)
      components[std::string(reactionName(dof))] = value;
  }
  return out;
}

namespace {

/// The catalogue's sections with the properties their tables print (SI units, the tables'
/// axes: y-y strong, which is a member's local z; see FORMAT.md).
Json catalogSectionsJson(const std::vector<DeckCatalogSection>& sections) {
  Json out = Json::array();
  for (const DeckCatalogSection& s : sections) {
    const CatalogProperties& p = s.properties;
    Json entry = {{"name", s.name},       {"designation", s.designation},
                  {"A", p.A},             {"Iy", p.Iy},
                  {"Iz", p.Iz},           {"It", p.It},
                  {"Wel_y", p.Wely},      {"Wel_z", p.Welz},
                  {"Wpl_y", p.Wply},      {"Wpl_z", p.Wplz},
                  {"axes", "tables' y-y (strong) = member local z"}};
    if (p.Iu > 0) {
      entry["Iu"] = p.Iu;
      entry["Iv"] = p.Iv;
    }
    out.push_back(entry);
  }
  return out;
}

}  // namespace

Json runJson(const RunResult& run) {
  if (!run.model) throw std::invalid_argument("run of '" + run.deckName + "' has no model");
  return runJson(run, runExtremes(run));
}

Json runJson(const RunResult& run, const std::vector<AnalysisExtremes>& extremes) {
  return runDocument(run, extremes).complete();
}

CaseEntries::CaseEntries(const Model& model, std::shared_ptr<const DofMap> dofs,
                         const std::array<bool, kDofKinds>& carried, const AnalysisOutcome& a,
                         const AnalysisExtremes& extremes, std::size_t analysis)
    : model_(&model),
      dofs_(std::move(dofs)),
      carried_(carried),
      cases_(&casesOf(a)),
      extremes_(&extremes.cases),
      stem_(fileStem(a.name)),
      memberDetail_(caseMemberDetail(model, casesOf(a).size())),
      analysis_(analysis),
      vtus_(casesOf(a).size()) {}

Json CaseEntries::entry(std::size_t i) const {
  Json out = caseJson(*model_, *dofs_, carried_, cases_->at(i), extremes_->at(i), stem_,
                      memberDetail_);
  if (!vtus_[i].empty()) out["vtu"] = vtus_[i];
  return out;
}

ResultsDocument runDocument(const RunResult& run, const std::vector<AnalysisExtremes>& extremes) {
  if (!run.model) throw std::invalid_argument("run of '" + run.deckName + "' has no model");
  if (extremes.size() != run.analyses.size())
    throw std::invalid_argument("runJson needs the extremes of every analysis");
  const Model& model = *run.model;
  const auto dofMap = std::make_shared<const DofMap>(model);
  const DofMap& dofs = *dofMap;
  const auto carried = kindsCarried(model, dofs);

  ResultsDocument out;
  Json& doc = out.doc;
  doc = objectWithRoom(16);
  doc["deck"] = {{"name", run.deckName}, {"path", run.deckPath}};
  doc["model"] = modelJson(run, dofs);
  Json analyses = Json::array();
  for (std::size_t i = 0; i < run.analyses.size(); ++i) {
    const AnalysisOutcome& a = run.analyses[i];
    analyses.push_back(std::visit(
        Overloaded{
            [&](const StaticOutcome&) {
              return staticJson(model, dofMap, carried, a, extremes[i], out.cases, i);
            },
            [&](const SecondOrderResult& r) {
              Json entry = staticJson(model, dofMap, carried, a, extremes[i], out.cases, i);
              entry["second_order"] = secondOrderJson(r);
              return entry;
            },
            [&](const BucklingResult&) { return bucklingJson(a); },
            [&](const ModalResult& r) { return modalJson(carried, a, r); },
            [&](const TorsionOutcome& r) {
              Json entry = modalJson(kindsCarried(*r.model, DofMap(*r.model)), a, r.modes);
              entry["free"] = r.free;
              if (!r.shafts.empty()) entry["train"] = torsionTrainJson(r, fileStem(a.name));
              return entry;
            },
            [&](const TransientOutcome&) { return transientJson(a); },
            [&](const RotorResult auto& r) { return rotorJson(a, r); },
            [&](const MovingLoadOutcome&) { return movingJson(a, fileStem(a.name)); },
            [&](const CrankSliderOutcome&) { return crankJson(a, fileStem(a.name)); },
            [&](const ResponseSpectrumResult& r) {
              Json entry = modalJson(carried, a, r.modal);
              entry.update(spectrumJson(a.type, a.name, r, model));
              return entry;
            },
            [&](const BaseMotionResult& r) { return baseMotionJson(a.type, a.name, r, model); }},
        a.result));
    if (!a.warnings.empty()) analyses.back()["warnings"] = a.warnings;
  }
  doc["analyses"] = std::move(analyses);
  doc["checks"] = checksJson(run.checks);
  doc["skipped_checks"] = run.skippedChecks;
  doc["parameters"] = parametersJson(run.parameters);
  if (!run.catalogSections.empty()) doc["catalog_sections"] = catalogSectionsJson(run.catalogSections);
  if (!run.warnings.empty()) doc["warnings"] = run.warnings;
  if (!run.reported.empty()) doc["reported"] = parametersJson(run.reported);
  if (run.adequate) doc["accuracy"] = adequateJson(*run.adequate);
  doc["seconds"] = run.seconds;
  doc["beamrotor_version"] = BEAMROTOR_VERSION;
  return out;
}

Json ResultsDocument::complete() const& { return ResultsDocument{doc, cases}.complete(); }

Json ResultsDocument::complete() && {
  for (const CaseEntries& c : cases) {
    Json& entries = doc.at("analyses").at(c.analysis()).at("cases");
    entries.get_ref<Json::array_t&>().reserve(c.size());
    for (std::size_t i = 0; i < c.size(); ++i) entries.push_back(c.entry(i));
  }
  return std::move(doc);
}

Json sweepJson(const SweepResult& sweep, const std::vector<Json>& runDocs,
               const std::vector<std::string>& directories) {
  if (runDocs.size() != sweep.values.size() || directories.size() != sweep.values.size())
    throw std::invalid_argument("sweepJson needs one document and directory per value");
  Json doc = {{"parameter", sweep.parameter}, {"values", sweep.values}};
  if (!runDocs.empty()) doc["model"] = runDocs.front().at("model");
  Json runs = Json::array();
  for (std::size_t i = 0; i < runDocs.size(); ++i) {
    Json analyses = Json::array();
    for (const Json& a : runDocs[i].at("analyses")) analyses.push_back(sweepAnalysisJson(a));
    Json entry = {{"value", sweep.values[i]}};
    if (!directories[i].empty()) entry["directory"] = directories[i];
    entry["parameters"] = runDocs[i].at("parameters");
    entry["reported"] = runDocs[i].value("reported", Json::object());
    entry["analyses"] = analyses;
    entry["checks"] = runDocs[i].at("checks");
    runs.push_back(entry);
  }
  doc["runs"] = runs;
  doc["worst"] = sweepWorstJson(sweep, runDocs);
  return doc;
}

void requireFiniteNumbers(const Json& doc, const std::string& document) {
  requireFiniteAt(doc, "", document);
}

namespace {

/// Where nlohmann's serializer puts its text: a buffer of its own, handed to the stream whenever
/// it fills, so that a document of hundreds of MB is never held as one string (its growth by
/// doubling held up to three times the file, all of it fresh memory the kernel zeroes).
class BufferedStreamOutput : public nlohmann::detail::output_adapter_protocol<char> {
 public:
  explicit BufferedStreamOutput(std::ostream& out) : out_(out) { buffer_.reserve(kBytes); }
  ~BufferedStreamOutput() override = default;
  BufferedStreamOutput(const BufferedStreamOutput&) = delete;
  BufferedStreamOutput& operator=(const BufferedStreamOutput&) = delete;

  void write_character(char c) override {
    buffer_.push_back(c);
    if (buffer_.size() >= kBytes) flush();
  }
  void write_characters(const char* s, std::size_t length) override {
    buffer_.append(s, length);
    if (buffer_.size() >= kBytes) flush();
  }
  void flush() {
    out_.write(buffer_.data(), std::streamsize(buffer_.size()));
    buffer_.clear();
  }

 private:
  static constexpr std::size_t kBytes = std::size_t(1) << 20;
  std::ostream& out_;
  std::string buffer_;
};

/// Writes a document as doc.dump(2, ' ', false, replace) gives it, in parts: nlohmann's own
/// serializer for each value, and the layout of its pretty printing (a container's entries one
/// a line, indented 2 more than it, separated by commas) around the containers that hold the
/// arrays made as they are written. Text that is not valid UTF-8 (a file name in another
/// encoding) is shown as U+FFFD rather than failing the whole write.
class JsonParts {
 public:
  explicit JsonParts(std::ostream& out)
      : buffered_(std::make_shared<BufferedStreamOutput>(out)),
        serializer_(buffered_, ' ', Json::error_handler_t::replace) {}

  /// A value written whole at an indentation of `indent`.
  void value(const Json& v, unsigned indent) { serializer_.dump(v, true, false, 2, indent); }
  /// An object's key as the serializer writes it, with its ": ".
  void key(const std::string& k) {
    serializer_.dump(Json(k), false, false, 0);
    buffered_->write_characters(": ", 2);
  }
  /// An object's (or array's) `count` entries, entry(k, its indentation) writing the k-th.
  template <class Entry>
  void container(bool object, std::size_t count, unsigned indent, const Entry& entry) {
    if (count == 0) {
      buffered_->write_characters(object ? "{}" : "[]", 2);
      return;
    }
    buffered_->write_characters(object ? "{\n" : "[\n", 2);
    const std::string spaces(indent + 2, ' ');
    for (std::size_t k = 0; k < count; ++k) {
      buffered_->write_characters(spaces.data(), spaces.size());
      entry(k, indent + 2);
      buffered_->write_characters(k + 1 < count ? ",\n" : "\n", k + 1 < count ? 2 : 1);
    }
    buffered_->write_characters(spaces.data(), indent);
    buffered_->write_character(object ? '}' : ']');
  }
  /// The last line's end, and everything handed to the stream.
  void finish() {
    buffered_->write_character('\n');
    buffered_->flush();
  }

 private:
  std::shared_ptr<BufferedStreamOutput> buffered_;
  nlohmann::detail::serializer<Json> serializer_;
};

}  // namespace

void writeJson(const Json& doc, const std::filesystem::path& file) {
  writeFile(file, [&](std::ostream& out) {
    JsonParts parts(out);
    parts.value(doc, 0);
    parts.finish();
  });
}

void ResultsDocument::write(
    const std::filesystem::path& file,
    const std::function<void(const CaseEntries&, const Json&)>& each) const {
  // The containers on the way to each cases array (the document, its analyses, the analysis)
  // are laid out here; every other value goes whole to the serializer.
  std::map<const Json*, const CaseEntries*> made;
  std::set<const Json*> around;
  for (const CaseEntries& c : cases) {
    const Json& analysis = doc.at("analyses").at(c.analysis());
    made[&analysis.at("cases")] = &c;
    around.insert({&doc, &doc.at("analyses"), &analysis});
  }
  writeFile(file, [&](std::ostream& out) {
    JsonParts parts(out);
    const auto write = [&](const auto& self, const Json& v, unsigned indent) -> void {
      if (const auto hole = made.find(&v); hole != made.end()) {
        const CaseEntries& c = *hole->second;
        parts.container(false, c.size(), indent, [&](std::size_t i, unsigned at) {
          throwIfInterrupted();
          const Json entry = c.entry(i);
          requireFiniteAt(entry,
                          "/analyses/" + std::to_string(c.analysis()) + "/cases/" +
                              std::to_string(i),
                          kResultsJson);
          parts.value(entry, at);
          if (each) each(c, entry);
        });
      } else if (!around.contains(&v)) {
        parts.value(v, indent);
      } else if (v.is_object()) {
        const auto& entries = v.get_ref<const Json::object_t&>();
        parts.container(true, entries.size(), indent, [&](std::size_t k, unsigned at) {
          const auto& [key, value] = *(entries.begin() + std::ptrdiff_t(k));
          parts.key(key);
          self(self, value, at);
        });
      } else {
        parts.container(false, v.size(), indent,
                        [&](std::size_t k, unsigned at) { self(self, v[k], at); });
      }
    };
    write(write, doc, 0);
    parts.finish();
  });
}

}  // namespace beamrotor
