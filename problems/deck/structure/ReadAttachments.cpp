// Deck reader, part 2: what is attached to the line at its points and along its segments:
// supports, springs, masses, hinges and loads.
#include <algorithm>
#include <optional>
#include <cmath>
#include <string>
#include <tuple>

#include "problems/deck/FieldUnits.hpp"
#include "problems/deck/ReaderContext.hpp"
#include "problems/deck/parse/Suggest.hpp"
#include "problems/deck/structure/StructureKinds.hpp"

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
  TakenNames names;
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
        record(value, d, value.number(c.evaluator, unitForDof(d, dim::length, dim::angle)));
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
  TakenNames names;
  const std::vector<Field> items = springs->items();
  for (const Field& f : items) {
    f.allowOnly({"name", "at", "to", "dof", "k", "c"}, "a spring");
    DeckSpring s;
    s.place = f.place();
    s.point = c.point(f.require("at")).name;
    if (auto n = f.get("name")) {
      s.name = n->name();
      claimName(*n, s.name, names, "a spring");
      // Outputs and `reaction NAME DOF` report a spring's force by its name, as a support's.
      for (const DeckSupport& support : c.deck.supports)
        if (support.name == s.name)
          n->fail("there is already a support named '" + s.name +
                  "'; a spring's force is reported by its name, so give it another");
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
  // A spring without a name goes by spring<N> (springName): no named one may take it.
  for (std::size_t i = 0; i < c.deck.springs.size(); ++i)
    if (!c.deck.springs[i].name.empty())
      for (std::size_t j = 0; j < c.deck.springs.size(); ++j)
        if (c.deck.springs[j].name.empty() && springName(c.deck, j) == c.deck.springs[i].name)
          items[i].require("name").fail("spring " + std::to_string(j + 1) +
                                        " has no name and goes by '" + c.deck.springs[i].name +
                                        "'; name this one otherwise");
}

/// The support holding dof d at point p, if any (in a line model, any point at p's place).
const DeckSupport* holder(const Context& c, const DeckPoint& p, Dof d) {
  const double tol = 1e-12 * std::max(1.0, c.deck.length());
  for (const DeckSupport& s : c.deck.supports) {
    const std::optional<int> at = c.pointNamed(s.point);
    const bool samePlace =
        s.point == p.name || (!c.deck.segments.empty() && !c.deck.frame && at &&
                              std::abs(c.deck.points[std::size_t(*at)].at - p.at) <= tol);
    if (!samePlace) continue;
    for (const auto& [dof, value] : s.dofs)
      if (dof == d) return &s;
  }
  return nullptr;
}

void readContacts(Context& c) {
  auto contacts = block(c, "contacts");
  if (!contacts) return;
  TakenNames names;
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

/// `rigid_links:` (a slave point following a master, all its dofs or those listed) and
/// `diaphragms:` (points following a master in a plane: its two translations and the rotation
/// about its normal, as far as the model carries them).
void readRigidLinks(Context& c) {
  TakenNames names;
  const auto tie = [&](const Field& f, const std::string& name, const Field& master,
                       const Field& slave, std::vector<Dof> dofs) {
    DeckRigidLink l{name, c.point(master).name, c.point(slave).name, std::move(dofs), f.place()};
    if (l.master == l.slave) slave.fail("a point cannot follow itself");
    for (const DeckRigidLink& other : c.deck.rigidLinks)
      if (other.slave == l.slave)
        slave.fail("point '" + l.slave + "' already follows '" + other.master + "' (" +
                   other.name + ")");
    // A chain (a master that follows a master) composes its rigid motions; a loop has no
    // first master. Each point follows at most one, so the masters form a path.
    std::string path = "'" + l.slave + "' -> '" + l.master + "'";
    for (std::string at = l.master;;) {
      const auto up = std::find_if(c.deck.rigidLinks.begin(), c.deck.rigidLinks.end(),
                                   [&](const DeckRigidLink& o) { return o.slave == at; });
      if (up == c.deck.rigidLinks.end()) break;
      at = up->master;
      path += " -> '";  // piece by piece: GCC 12's false -Wrestrict
      path += at;
      path += "'";
      if (at == l.slave)
        slave.fail("the ties would form a loop (" + path +
                   ", each point following the next): a chain of ties needs a first master "
                   "that follows nothing");
    }
    for (Dof d : l.dofs)
      if (const DeckSupport* s = holder(c, c.point(slave), d))
        slave.fail(std::string(dofName(d)) + " at point '" + l.slave + "' is held by support '" +
                   s->name + "'; a point that follows its master cannot be held too");
    c.deck.rigidLinks.push_back(std::move(l));
  };
  if (auto links = block(c, "rigid_links"))
    for (const Field& f : links->items()) {
      f.allowOnly({"name", "master", "slave", "dofs"}, "a rigid link");
      const Field name = f.require("name");
      claimName(name, name.name(), names, "a rigid link or diaphragm");
      std::vector<Dof> dofs;
      if (auto list = f.get("dofs"))
        for (const Field& d : list->itemsOrSingle()) dofs.push_back(c.dof(d));
      else
        for (Dof d : kAllDofs)
          if (c.deck.dofs.contains(d)) dofs.push_back(d);
      tie(f, name.name(), f.require("master"), f.require("slave"), std::move(dofs));
    }
  if (auto diaphragms = block(c, "diaphragms"))
    for (const Field& f : diaphragms->items()) {
      f.allowOnly({"name", "master", "points", "plane"}, "a diaphragm");
      const Field name = f.require("name");
      claimName(name, name.name(), names, "a rigid link or diaphragm");
      // The plane's two translations and the rotation about its normal.
      const std::string plane = f.require("plane").choice({"xy", "xz", "yz"});
      const std::vector<Dof> inPlane = plane == "xy"   ? std::vector{Dof::ux, Dof::uy, Dof::rz}
                                       : plane == "xz" ? std::vector{Dof::ux, Dof::uz, Dof::ry}
                                                       : std::vector{Dof::uy, Dof::uz, Dof::rx};
      std::vector<Dof> dofs;
      for (Dof d : inPlane)
        if (c.deck.dofs.contains(d)) dofs.push_back(d);
      const Field points = f.require("points");
      if (!points.isList() || points.items().empty())
        points.fail("a diaphragm ties a list of points to its master, got " + points.describe());
      for (const Field& p : points.items()) tie(f, name.name(), f.require("master"), p, dofs);
    }
}

void readMasses(Context& c) {
  auto masses = block(c, "masses");
  if (!masses) return;
  TakenNames names;
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
    m.m = mf.nonNegative(c.evaluator, dim::mass);
    if (auto J = f.get("Jp")) m.Jp = J->nonNegative(c.evaluator, dim::inertia);
    if (auto J = f.get("Jd")) m.Jd = J->nonNegative(c.evaluator, dim::inertia);
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

/// qx, qy, qz of a distributed load: one number (uniform) or [start, end] (linear from the
/// loaded part's start to its end: a trapezoid, or a triangle with a zero).
void readDistributedValues(const Context& c, const Field& f, DeckLoad& l) {
  bool any = false;
  for (int k = 0; k < 3; ++k) {
    const std::string key = std::string("q") + "xyz"[k];
    auto v = f.get(key);
    if (!v) continue;
    if (!c.deck.dofs.contains(kAllDofs[k]))
      v->fail(key + " acts along " + std::string(dofName(kAllDofs[k])) + ", not a dof of a " +
              c.deck.dimension + " model");
    if (v->isList()) {
      const std::vector<Field> ends = v->items();
      if (ends.size() != 2)
        v->fail("a varying load gives two values, [at its start, at its end] (N/m), got " +
                std::to_string(ends.size()));
      l.q[k] = ends[0].number(c.evaluator, dim::forcePerLength);
      l.qEnd[k] = ends[1].number(c.evaluator, dim::forcePerLength);
    } else {
      l.q[k] = l.qEnd[k] = v->number(c.evaluator, dim::forcePerLength);
    }
    any = true;
  }
  if (!any) f.fail("a distributed load needs at least one of qx, qy, qz (N/m)");
}

/// Every segment's (or member's) index.
std::vector<int> allSegments(const Context& c) {
  std::vector<int> out(c.deck.segments.size());
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = int(i);
  return out;
}

/// A mesh node where a partial load starts or ends, at `fraction` of segment or member i: a
/// member station in a frame, a point on the line otherwise (named NAME@FRACTION).
void addLoadBoundary(Context& c, int i, double fraction, const DeckPlace& place) {
  if (c.deck.frame) return addMemberStation(c, i, fraction, place);
  if (fraction == 0 || fraction == 1) return;
  double start = 0;
  for (int k = 0; k < i; ++k) start += c.deck.segments[k].length;
  const double x = start + fraction * c.deck.segments[i].length;
  for (const DeckPoint& p : c.deck.points)
    if (p.at == x) return;
  const std::string& name = c.deck.segments[i].name;
  c.deck.points.push_back(
      {fractionPlaceName(name.empty() ? "segment" + std::to_string(i) : name, fraction), x, place});
}

/// `from:`/`to:` (fractions of the length) or `from_length:`/`to_length:` (m from the start):
/// the part of each loaded segment or member the load covers (all of it by default). Its ends
/// become mesh nodes, so that every element is loaded over its whole length or not at all.
void readLoadedPart(Context& c, const Field& f, DeckLoad& l) {
  const auto end = [&](const char* fractionKey, const char* lengthKey, double whole) {
    const auto fraction = f.get(fractionKey), length = f.get(lengthKey);
    if (fraction && length)
      length->fail(std::string("give either ") + fractionKey + " (a fraction) or " + lengthKey +
                   " (m), not both");
    if (!fraction && !length) return whole;
    const Field& given = fraction ? *fraction : *length;
    const double value = given.number(c.evaluator, fraction ? dim::none : dim::length);
    if (fraction) {
      if (!(value >= 0 && value <= 1))
        given.fail("a fraction of the length lies in [0, 1], got " + formatNumber(value));
      return value;
    }
    // A length: from the start of the one segment or member loaded.
    if (l.segments.size() != 1)
      given.fail(std::string(lengthKey) + " measures along one segment or member: name it (" +
                 (c.deck.frame ? "member:" : "segment:") + "), or give " + fractionKey +
                 " as a fraction of each");
    const DeckSegment& s = c.deck.segments[l.segments.front()];
    if (!(value >= 0 && value <= s.length))
      given.fail("'" + s.name + "' is " + formatNumber(s.length) + " m long; " + lengthKey +
                 " lies in [0, " + formatNumber(s.length) + "], got " + formatNumber(value));
    return value / s.length;
  };
  l.from = end("from", "from_length", 0);
  l.to = end("to", "to_length", 1);
  if (!(l.from < l.to))
    (f.has("to") ? f.require("to") : f.has("to_length") ? f.require("to_length") : f)
        .fail("the loaded part ends where it starts or before (from " + formatNumber(l.from) +
              ", to " + formatNumber(l.to) + " of the length)");
  if (l.from == 0 && l.to == 1) return;
  for (int i : l.segments.empty() ? allSegments(c) : l.segments)
    for (double fraction : {l.from, l.to}) addLoadBoundary(c, i, fraction, f.place());
}

/// A temperature change on segments or members: `dT` at the centroid and its rise through the
/// depth `dT_y`, `dT_z` (K), on materials that give their `alpha`.
void readTemperature(const Context& c, const Field& f, DeckLoad& l) {
  f.allowOnly({"type", "segment", "member", "dT", "dT_y", "dT_z"}, "a temperature load");
  l.kind = DeckLoad::Kind::temperature;
  l.segments = loadedSegments(c, f);
  const ExpressionEvaluator& ev = c.evaluator;
  bool any = false;
  for (const auto& [key, value, bends] :
       {std::tuple{"dT", &l.dT, Dof::ux}, std::tuple{"dT_y", &l.dTy, Dof::rz},
        std::tuple{"dT_z", &l.dTz, Dof::ry}}) {
    auto v = f.get(key);
    if (!v) continue;
    if (!c.deck.dofs.contains(bends))
      v->fail(std::string(key) + (bends == Dof::ux ? " stretches along " : " bends about ") +
              std::string(dofName(bends)) + ", not a dof of a " +
              c.deck.dimension + " model");
    *value = v->number(ev, dim::temperature);
    any = true;
  }
  if (!any) f.fail("a temperature load needs at least one of dT, dT_y, dT_z (K)");
  for (int i = 0; i < int(c.deck.segments.size()); ++i) {
    if (!l.segments.empty() && std::find(l.segments.begin(), l.segments.end(), i) == l.segments.end())
      continue;
    const Section& s = *c.deck.segments[i].section;
    const std::string& name = c.deck.segments[i].name;
    const std::string what = c.deck.frame     ? "member '" + name + "'"
                             : name.empty() ? "segment " + std::to_string(i)
                                            : "segment '" + name + "'";
    if (!(s.material.alpha > 0))
      f.fail("a temperature load needs the thermal expansion of material '" + s.material.name +
             "' of " + what + ": give it alpha (1/K, e.g. 12e-6/K for steel)");
    try {
      thermalStrain(s, l.dT, l.dTy, l.dTz);
    } catch (const std::invalid_argument& e) {
      f.fail(std::string(e.what()) + " (" + what + ")");
    }
  }
}

/// The loads of one list (`loads:` or a load case's `loads:`), appended to out.
void readLoadList(Context& c, const Field& list, std::vector<DeckLoad>& out) {
  const ExpressionEvaluator& ev = c.evaluator;
  for (const Field& f : list.items()) {
    if (!f.isMap()) f.fail("expected a map describing a load, got " + f.describe());
    const std::string type =
        f.require("type").choice({"point", "distributed", "self-weight", "temperature"});
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
        l.components.emplace_back(d, v->number(ev, unitForDof(d, dim::force, dim::moment)));
      }
      if (l.components.empty())
        f.fail("a point load needs at least one of fx, fy, fz (N) or mx, my, mz (N m)");
    } else if (c.deck.segments.empty()) {
      f.fail("a " + type +
             " load acts on segments, and this deck has none (a model without "
             "beams takes point loads)");
    } else if (type == "distributed") {
      f.allowOnly({"type", "segment", "member", "axes", "per", "from", "to", "from_length",
                   "to_length", "qx", "qy", "qz"},
                  "a distributed load");
      l.kind = DeckLoad::Kind::distributed;
      l.segments = loadedSegments(c, f);
      if (auto axes = f.get("axes")) l.inMemberAxes = axes->choice({"global", "member"}) == "member";
      if (auto per = f.get("per")) {
        l.perProjectedLength = per->choice({"length", "projected"}) == "projected";
        if (l.perProjectedLength && l.inMemberAxes)
          per->fail("a load per projected length acts in global axes (axes: global): its "
                    "components are per length of the member's projection across each of them");
      }
      readDistributedValues(c, f, l);
      readLoadedPart(c, f, l);
    } else if (type == "temperature") {
      readTemperature(c, f, l);
    } else {
      f.allowOnly({"type", "segment", "member", "g"}, "a self-weight load");
      l.kind = DeckLoad::Kind::selfWeight;
      l.segments = loadedSegments(c, f);
      if (auto g = f.get("g")) l.g = g->positive(ev, dim::acceleration);
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
  TakenNames names;
  if (auto cases = block(c, "load_cases")) {
    for (const Field& f : cases->items()) {
      if (!f.isMap()) f.fail("expected a map {name:, loads: [...]}, got " + f.describe());
      f.allowOnly({"name", "loads"}, "a load case");
      DeckLoadCase lc;
      lc.place = f.place();
      const Field nameField = f.require("name");
      lc.name = nameField.text();
      claimName(nameField, lc.name, names, "a load case or combination");
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
      claimName(nameField, k.name, names, "a load case or combination");
      for (const auto& [key, value] : f.require("factors").entries()) {
        // A named copy: clang 14 (the fuzz build's) cannot capture a structured binding.
        const std::string& caseName = key;
        const bool known =
            std::any_of(c.deck.loadCases.begin(), c.deck.loadCases.end(),
                        [&](const DeckLoadCase& lc) { return lc.name == caseName; });
        if (!known) value.fail("no load case '" + key + "' (load_cases: defines the names)");
        k.factors.emplace_back(key, value.number(c.evaluator, dim::none));
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
  if (c.deck.frame && c.deck.frame->hasOneWayMembers())
    block(c, "load_cases")
        ->fail("load cases are superposed, and tension-only or compression-only members "
               "(acts:) are not linear: remove acts: or the load cases");
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
  readRigidLinks(c);
  readMasses(c);
  readHinges(c);
  readLoads(c);
  readLoadCases(c);
  // A model without beams needs something to move and something to hold it (a deck of
  // mechanism analyses alone has neither beams nor points, and needs no model).
  if (!c.deck.segments.empty() || c.deck.points.empty()) return;
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

void refuseTiedAnalyses(const Context& c) {
  if (c.deck.rigidLinks.empty()) return;
  for (const DeckAnalysis& a : c.deck.analyses) {
    // The frame analyses eliminate the ties (fem/assembly/RigidTies.hpp): the statics, first
    // and second order, and what they drive (moving loads, buckling), the modes and what
    // rests on them (response spectra, base motion).
    if (a.as<StaticSpec>() || a.as<ModalSpec>() || a.as<BucklingSpec>() ||
        a.as<MovingLoadSpec>() || a.as<ResponseSpectrumSpec>() || a.as<BaseMotionSpec>())
      continue;
    throw DeckError(c.deck.path, a.place,
                    "rigid links, offsets and diaphragms are eliminated in the frame analyses "
                    "(static, modal, buckling, moving-load, response-spectrum, base-motion) "
                    "only; the " + a.type() + " analysis '" + a.name +
                    "' would ignore them: remove it or the ties");
  }
}

}  // namespace beamrotor::reader
