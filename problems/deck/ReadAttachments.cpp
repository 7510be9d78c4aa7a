// Deck reader, part 2: what is attached to the line at its points and along its segments:
// supports, springs, masses, hinges and loads.
#include <algorithm>
#include <cmath>
#include <tuple>

#include "problems/deck/FieldUnits.hpp"
#include "problems/deck/ReaderContext.hpp"
#include "problems/deck/Suggest.hpp"

namespace beamrotor::reader {

namespace {

std::optional<Field> block(const Context& c, const std::string& key) {
  auto f = c.root.get(key);
  if (!f || f->isNull()) return std::nullopt;
  return f;
}

/// Dofs of a `fix:` field: a list of dof names, one name, or the shorthand clamped (every
/// dof the model carries) or pinned (its translations).
std::vector<Dof> fixedDofs(const Context& c, const Field& f) {
  std::vector<Dof> dofs;
  if (f.isScalar() && (f.text() == "clamped" || f.text() == "pinned")) {
    const bool clamped = f.text() == "clamped";
    for (Dof d : kAllDofs)
      if (c.deck.dofs.contains(d) && (clamped || !isRotation(d))) dofs.push_back(d);
    return dofs;
  }
  if (!f.isScalar() && !f.isList())
    f.fail("expected clamped, pinned or a list of dofs such as [ux, uy], got " + f.describe());
  for (const Field& item : f.itemsOrSingle()) {
    if (!item.isScalar() || !parseDof(item.text()))
      item.fail("expected a dof (" + c.carriedNames() + ") or clamped / pinned, got " +
                item.describe());
    const Dof d = c.dof(item);
    if (std::find(dofs.begin(), dofs.end(), d) != dofs.end())
      item.fail(std::string(dofName(d)) + " is listed twice");
    dofs.push_back(d);
  }
  return dofs;
}

void readSupports(Context& c) {
  auto supports = block(c, "supports");
  if (!supports) return;
  std::vector<std::string> names;
  // Which support already holds each (position, dof): two supports on one dof conflict.
  std::vector<std::tuple<double, Dof, std::string, std::string>> held;  // + the point's name
  const double tol = 1e-12 * std::max(1.0, c.deck.length());
  for (const Field& f : supports->items()) {
    f.allowOnly({"name", "at", "fix", "prescribe"}, "a support");
    DeckSupport s;
    s.place = f.place();
    const Field at = f.require("at");
    const DeckPoint& p = c.point(at);
    s.point = p.name;
    auto nameField = f.get("name");
    s.name = nameField ? nameField->name() : p.name;
    claimName(nameField ? *nameField : at, s.name, names, "a support");
    auto record = [&](const Field& where, Dof d, double value) {
      for (const auto& [x, dof, owner, point] : held)
        if (dof == d && (c.deck.frame ? point == p.name : std::abs(x - p.at) <= tol))
          where.fail(std::string(dofName(d)) + " at point '" + p.name +
                     "' is already held by support '" + owner + "'");
      for (const auto& [dof, v] : s.dofs)
        if (dof == d)
          where.fail(std::string(dofName(d)) + " is both fixed and prescribed; give it once");
      s.dofs.emplace_back(d, value);
    };
    if (auto fix = f.get("fix"))
      for (Dof d : fixedDofs(c, *fix)) record(*fix, d, 0);
    if (auto prescribe = f.get("prescribe"))
      for (const auto& [key, value] : prescribe->entries()) {
        if (!parseDof(key))
          value.fail("'" + key + "' is not a dof (" + c.carriedNames() + ")" +
                     didYouMean(key, {"ux", "uy", "uz", "rx", "ry", "rz"}));
        const Dof d = *parseDof(key);
        if (!c.deck.dofs.contains(d))
          value.fail(key + " is not a dof of a " + c.deck.dimension + " model (" +
                     c.carriedNames() + ")");
        record(value, d, value.number(c.evaluator));
      }
    if (s.dofs.empty())
      f.fail("support '" + s.name +
             "' holds nothing: give fix (e.g. clamped, pinned, [uy]) "
             "or prescribe (e.g. {uy: -0.001})");
    for (const auto& [d, v] : s.dofs) held.emplace_back(p.at, d, s.name, p.name);
    c.deck.supports.push_back(std::move(s));
  }
}

void readSprings(Context& c) {
  auto springs = block(c, "springs");
  if (!springs) return;
  std::vector<std::string> names;
  for (const Field& f : springs->items()) {
    f.allowOnly({"name", "at", "to", "dof", "k", "c"}, "a spring");
    DeckSpring s;
    s.place = f.place();
    s.point = c.point(f.require("at")).name;
    if (auto n = f.get("name")) {
      s.name = n->name();
      claimName(*n, s.name, names, "a spring");
    }
    if (auto to = f.get("to")) {
      const DeckPoint& q = c.point(*to);
      if (q.name == s.point)
        to->fail("a spring needs two different points (or no 'to' for a grounded spring)");
      s.toPoint = q.name;
    }
    s.dof = c.dof(f.require("dof"));
    const Field k = f.require("k");
    s.k = k.nonNegative(c.evaluator, unitForDof(s.dof, dim::stiffness, dim::rotationalStiffness));
    if (auto cf = f.get("c"))
      s.c = cf->nonNegative(c.evaluator, unitForDof(s.dof, dim::damping, dim::rotationalDamping));
    if (s.k == 0 && s.c == 0) k.fail("a spring needs a positive stiffness k (or damping c)");
    c.deck.springs.push_back(std::move(s));
  }
}

/// The support holding dof d at point p, if any (in a line model, any point at p's place).
const DeckSupport* holder(const Context& c, const DeckPoint& p, Dof d) {
  const double tol = 1e-12 * std::max(1.0, c.deck.length());
  for (const DeckSupport& s : c.deck.supports) {
    const auto at = std::find_if(c.deck.points.begin(), c.deck.points.end(),
                                 [&](const DeckPoint& q) { return q.name == s.point; });
    const bool samePlace =
        s.point == p.name ||
        (!c.deck.segments.empty() && !c.deck.frame && at != c.deck.points.end() &&
         std::abs(at->at - p.at) <= tol);
    if (!samePlace) continue;
    for (const auto& [dof, value] : s.dofs)
      if (dof == d) return &s;
  }
  return nullptr;
}

void readContacts(Context& c) {
  auto contacts = block(c, "contacts");
  if (!contacts) return;
  std::vector<std::string> names;
  for (const Field& f : contacts->items()) {
    f.allowOnly({"name", "at", "dof", "min", "max"}, "a contact");
    DeckContact k;
    k.place = f.place();
    const DeckPoint& p = c.point(f.require("at"));
    k.point = p.name;
    const Field name = f.require("name");
    k.name = name.name();
    claimName(name, k.name, names, "a contact");
    const Field dof = f.require("dof");
    k.dof = c.dof(dof);
    if (const DeckSupport* s = holder(c, p, k.dof))
      dof.fail(std::string(dofName(k.dof)) + " at point '" + p.name + "' is held by support '" +
               s->name + "'; a contact there would never act: remove one of the two");
    const auto lower = f.get("min"), upper = f.get("max");
    if (!lower && !upper) f.fail("a contact needs a bound: min, max or both");
    const FieldUnit bound = unitForDof(k.dof, dim::length, dim::angle);
    if (lower) k.lower = lower->number(c.evaluator, bound);
    if (upper) k.upper = upper->number(c.evaluator, bound);
    if (lower && upper && !(k.lower < k.upper))
      upper->fail("max must exceed min (" + std::to_string(k.lower) + ")");
    c.deck.contacts.push_back(std::move(k));
  }
}

void readMasses(Context& c) {
  auto masses = block(c, "masses");
  if (!masses) return;
  std::vector<std::string> names;
  for (const Field& f : masses->items()) {
    f.allowOnly({"name", "at", "m", "Jp", "Jd", "disk"}, "a mass");
    DeckMass m;
    m.place = f.place();
    m.point = c.point(f.require("at")).name;
    if (auto n = f.get("name")) {
      m.name = n->name();
      claimName(*n, m.name, names, "a mass");
    }
    if (auto disk = f.get("disk")) {
      for (const char* key : {"m", "Jp", "Jd"})
        if (auto given = f.get(key)) given->fail("give either the disk's geometry or m, Jp, Jd");
      readDisk(c, *disk, m);
      c.deck.masses.push_back(std::move(m));
      continue;
    }
    const Field mf = f.require("m");
    m.m = mf.nonNegative(c.evaluator);
    if (auto J = f.get("Jp")) m.Jp = J->nonNegative(c.evaluator);
    if (auto J = f.get("Jd")) m.Jd = J->nonNegative(c.evaluator);
    if (m.m == 0 && m.Jp == 0 && m.Jd == 0) mf.fail("a mass needs m, Jp or Jd positive");
    c.deck.masses.push_back(std::move(m));
  }
}

void readHinges(Context& c) {
  auto hinges = block(c, "hinges");
  if (!hinges) return;
  for (const Field& f : hinges->items()) {
    f.allowOnly({"at", "release"}, "a hinge");
    DeckHinge h;
    h.place = f.place();
    h.point = c.point(f.require("at")).name;
    if (auto release = f.get("release")) {
      for (const Field& item : release->itemsOrSingle()) {
        const Dof d = c.rotation(item);
        if (std::find(h.released.begin(), h.released.end(), d) != h.released.end())
          item.fail(std::string(dofName(d)) + " is listed twice");
        h.released.push_back(d);
      }
    } else if (c.deck.dimension == "planar") {
      h.released = {Dof::rz};
    } else {
      h.released = {Dof::ry, Dof::rz};  // a bending hinge; torsion still passes
    }
    for (const DeckHinge& other : c.deck.hinges)
      if (other.point == h.point) f.fail("point '" + h.point + "' already has a hinge");
    c.deck.hinges.push_back(std::move(h));
  }
}

/// The segments a load acts on: `segment:` (or, in a frame, `member:`) names one or a list;
/// absent means all.
std::vector<int> loadedSegments(const Context& c, const Field& load) {
  std::vector<int> out;
  auto f = load.get(c.deck.frame ? "member" : "segment");
  if (c.deck.frame && load.has("segment"))
    load.require("segment").fail("a frame's loads name members: write member: instead");
  if (!c.deck.frame && load.has("member"))
    load.require("member").fail("this deck is a line of segments (no members): write segment:");
  if (f)
    for (const Field& item : f->itemsOrSingle()) out.push_back(c.segment(item));
  return out;
}

/// The loads of one list (`loads:` or a load case's `loads:`), appended to out.
void readLoadList(Context& c, const Field& list, std::vector<DeckLoad>& out) {
  const ExpressionEvaluator& ev = c.evaluator;
  for (const Field& f : list.items()) {
    if (!f.isMap()) f.fail("expected a map describing a load, got " + f.describe());
    const std::string type = f.require("type").choice({"point", "distributed", "self-weight"});
    DeckLoad l;
    l.place = f.place();
    if (type == "point") {
      const std::vector<std::string> components{"fx", "fy", "fz", "mx", "my", "mz"};
      std::vector<std::string> keys{"type", "at"};
      keys.insert(keys.end(), components.begin(), components.end());
      f.allowOnly(keys, "a point load");
      l.kind = DeckLoad::Kind::point;
      l.point = c.point(f.require("at")).name;
      for (int k = 0; k < kDofKinds; ++k) {
        auto v = f.get(components[k]);
        if (!v) continue;
        const Dof d = kAllDofs[k];
        if (!c.deck.dofs.contains(d))
          v->fail(components[k] + " acts on " + std::string(dofName(d)) + ", not a dof of a " +
                  c.deck.dimension + " model (" + c.carriedNames() + ")");
        l.components.emplace_back(d, v->number(ev));
      }
      if (l.components.empty())
        f.fail("a point load needs at least one of fx, fy, fz (N) or mx, my, mz (N m)");
    } else if (c.deck.segments.empty()) {
      f.fail("a " + type +
             " load acts on segments, and this deck has none (a model without "
             "beams takes point loads)");
    } else if (type == "distributed") {
      f.allowOnly({"type", "segment", "member", "axes", "qx", "qy", "qz"}, "a distributed load");
      l.kind = DeckLoad::Kind::distributed;
      l.segments = loadedSegments(c, f);
      if (auto axes = f.get("axes")) l.inMemberAxes = axes->choice({"global", "member"}) == "member";
      bool any = false;
      for (int k = 0; k < 3; ++k) {
        const std::string key = std::string("q") + "xyz"[k];
        auto v = f.get(key);
        if (!v) continue;
        if (!c.deck.dofs.contains(kAllDofs[k]))
          v->fail(key + " acts along " + std::string(dofName(kAllDofs[k])) + ", not a dof of a " +
                  c.deck.dimension + " model");
        l.q[k] = v->number(ev);
        any = true;
      }
      if (!any) f.fail("a distributed load needs at least one of qx, qy, qz (N/m)");
    } else {
      f.allowOnly({"type", "segment", "member", "g"}, "a self-weight load");
      l.kind = DeckLoad::Kind::selfWeight;
      l.segments = loadedSegments(c, f);
      if (auto g = f.get("g")) l.g = g->positive(ev);
      for (int i = 0; i < int(c.deck.segments.size()); ++i) {
        const bool loaded = l.segments.empty() ||
                            std::find(l.segments.begin(), l.segments.end(), i) != l.segments.end();
        if (loaded && !(c.deck.segments[i].section->material.rho > 0))
          f.fail("self-weight needs a density: material '" +
                 c.deck.segments[i].section->material.name + "' of segment " + std::to_string(i) +
                 " has no rho");
      }
    }
    out.push_back(std::move(l));
  }
}

void readLoads(Context& c) {
  if (auto loads = block(c, "loads")) readLoadList(c, *loads, c.deck.loads);
}

/// `load_cases:` (named lists of loads) and `combinations:` (factors on those names).
void readLoadCases(Context& c) {
  std::vector<std::string> names;
  if (auto cases = block(c, "load_cases")) {
    for (const Field& f : cases->items()) {
      if (!f.isMap()) f.fail("expected a map {name:, loads: [...]}, got " + f.describe());
      f.allowOnly({"name", "loads"}, "a load case");
      DeckLoadCase lc;
      lc.place = f.place();
      const Field nameField = f.require("name");
      lc.name = nameField.text();
      if (std::find(names.begin(), names.end(), lc.name) != names.end())
        nameField.fail("load case '" + lc.name + "' is defined twice");
      names.push_back(lc.name);
      const Field list = f.require("loads");
      if (!list.isList()) list.fail("expected a list of loads, got " + list.describe());
      readLoadList(c, list, lc.loads);
      c.deck.loadCases.push_back(std::move(lc));
    }
  }
  if (auto combos = block(c, "combinations")) {
    if (c.deck.loadCases.empty())
      combos->fail("combinations factor load cases: define them under load_cases:");
    for (const Field& f : combos->items()) {
      if (!f.isMap()) f.fail("expected a map {name:, factors: {case: factor}}, got " + f.describe());
      f.allowOnly({"name", "factors"}, "a combination");
      DeckCombination k;
      k.place = f.place();
      const Field nameField = f.require("name");
      k.name = nameField.text();
      if (std::find(names.begin(), names.end(), k.name) != names.end())
        nameField.fail("'" + k.name + "' already names a load case or combination");
      names.push_back(k.name);
      for (const auto& [key, value] : f.require("factors").entries()) {
        const bool known = std::any_of(c.deck.loadCases.begin(), c.deck.loadCases.end(),
                                       [&](const DeckLoadCase& lc) { return lc.name == key; });
        if (!known) value.fail("no load case '" + key + "' (load_cases: defines the names)");
        k.factors.emplace_back(key, value.number(c.evaluator));
      }
      if (k.factors.empty()) f.require("factors").fail("a combination needs at least one factor");
      c.deck.combinations.push_back(std::move(k));
    }
  }
  if (c.deck.loadCases.empty()) return;
  // Cases are superposed: the model must be linear in its loads.
  if (!c.deck.contacts.empty())
    block(c, "load_cases")->fail("load cases are superposed, and contacts are not linear: "
                                 "remove contacts: or the load cases");
  for (const DeckSupport& s : c.deck.supports)
    for (const auto& [d, value] : s.dofs)
      if (value != 0)
        block(c, "load_cases")
            ->fail("load cases are superposed: support '" + s.name +
                   "' prescribes a nonzero value, which every case would repeat");
}

}  // namespace

void readAttachments(Context& c) {
  readSupports(c);
  readSprings(c);
  readContacts(c);
  readMasses(c);
  readHinges(c);
  readLoads(c);
  readLoadCases(c);
  // A model without beams needs something to move and something to hold it.
  if (!c.deck.segments.empty()) return;
  if (c.deck.masses.empty())
    block(c, "springs")
        .value_or(c.root)
        .fail("a model without segments (beams) needs at least one mass (masses:) on its points");
  if (c.deck.springs.empty())
    block(c, "masses")
        ->fail(
            "a model without segments (beams) needs at least one spring "
            "(springs:) to hold its masses");
}

}  // namespace beamrotor::reader
