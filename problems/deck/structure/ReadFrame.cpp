// Deck reader, part 1b: a frame. `nodes:` are named joints with coordinates, `members:`
// straight beams between them (one deck segment each: section, mesh, formulation), with
// their orientation and end releases, and `points:` name places along members. Attachments
// may also name a place on a member inline, `{member: NAME, at: FRACTION}`: those places
// are collected here, before the attachments are read, so that every one is a point.
#include <algorithm>
#include <array>
#include <cstdint>
#include <unordered_map>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "problems/deck/DeckReader.hpp"
#include "problems/deck/ReaderContext.hpp"
#include "problems/deck/parse/Suggest.hpp"

namespace beamrotor::reader {

namespace {

/// Most beam elements a frame deck may ask for (a line keeps kMaxElements): a building of 10^5
/// members at 5 elements each (512,160 elements, 2.7x10^6 dofs) ran in a peak of 5.6 GB, its
/// factor 3e8 entries (docs/performance.md). A 3D frame's factor grows faster than its
/// elements (its fill as about elements^1.5), so the cap stays near that size: a typo cannot
/// ask for much more than about 7 GB. requireMemory (problems/run) still refuses a run the
/// machine cannot hold.
constexpr int kMaxFrameElements = 600000;

/// Fractions this close to a member's end are the joint itself.
constexpr double kEndTolerance = 1e-12;

/// A vector of 2 (planar) or 3 (3d) numbers, z = 0 in planar models: a node's place (lengths)
/// or a direction (plain numbers, whose size does not matter).
Eigen::Vector3d coordinates(const Context& c, const Field& f, const std::string& what,
                            const Dimension& d) {
  const bool planar = c.deck.dimension == "planar";
  const std::size_t n = planar ? 2 : 3;
  if (!f.isList() || f.items().size() != n)
    f.fail("expected " + what + " as " + (planar ? "[x, y]" : "[x, y, z]") + " in a " +
           c.deck.dimension + " model, got " + f.describe());
  Eigen::Vector3d x = Eigen::Vector3d::Zero();
  const std::vector<Field> items = f.items();
  for (std::size_t k = 0; k < n; ++k) x[k] = items[k].number(c.evaluator, d);
  return x;
}

/// The index of the joint a field names.
int jointIndex(const Context& c, const Field& f) {
  const std::string name = f.name();
  const auto& joints = c.deck.frame->joints;
  if (const auto j = c.jointNamed(name)) return *j;
  std::vector<std::string> names;
  for (const DeckJoint& j : joints) names.push_back(j.name);
  f.fail("no node named '" + name + "'" + didYouMean(name, names) + " (nodes: " +
         joinNames(names) + ")");
}

/// Fails at the first node that lies on an earlier one (within 1e-12 of its distance from the
/// origin, at least 1e-12), naming the first such earlier node. Nodes are binned in cubes of
/// twice the largest such tolerance, so two nodes that meet share a cube or touch neighbouring
/// ones: one pass over the nodes (bin indices stay below 5e11, as no node is farther from the
/// origin than 1e12 tolerances).
void refuseCoincidentJoints(const std::vector<DeckJoint>& joints, const std::vector<Field>& items) {
  const auto tolerance = [](const Eigen::Vector3d& x) { return 1e-12 * std::max(1.0, x.norm()); };
  double reach = 0;
  for (const DeckJoint& j : joints) reach = std::max(reach, tolerance(j.x));
  const double side = 2 * reach;
  using Bin = std::array<std::int64_t, 3>;
  struct BinHash {
    std::size_t operator()(const Bin& b) const {
      std::size_t h = 0;
      for (std::int64_t v : b) h = h * 1000003u ^ std::hash<std::int64_t>{}(v);
      return h;
    }
  };
  std::unordered_map<Bin, std::vector<int>, BinHash> bins;
  for (int j = 0; j < int(joints.size()); ++j) {
    const Eigen::Vector3d& x = joints[j].x;
    Bin bin;
    for (int k = 0; k < 3; ++k) bin[k] = std::int64_t(std::floor(x[k] / side));
    int first = -1;
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dz = -1; dz <= 1; ++dz) {
          const auto near = bins.find({bin[0] + dx, bin[1] + dy, bin[2] + dz});
          if (near == bins.end()) continue;
          for (int other : near->second)
            if ((joints[other].x - x).norm() <= tolerance(x) && (first < 0 || other < first))
              first = other;
        }
    if (first >= 0)
      items[j].require("at").fail("node '" + joints[j].name + "' lies on node '" +
                                  joints[first].name + "'; a member joins two different places");
    bins[bin].push_back(j);
  }
}

void readJoints(Context& c, TakenNames& pointNames) {
  const Field block = c.root.require("nodes");
  for (const Field& f : block.items()) {
    f.allowOnly({"name", "at"}, "a node");
    const Field nf = f.require("name");
    DeckJoint j{nf.name(), coordinates(c, f.require("at"), "a node's coordinates", dim::length),
                f.place()};
    claimName(nf, j.name, pointNames, "a point or node");
    c.deck.points.push_back({j.name, 0, j.place});
    c.deck.frame->joints.push_back(std::move(j));
  }
  if (c.deck.frame->joints.size() < 2) block.fail("a frame needs at least two nodes");
  refuseCoincidentJoints(c.deck.frame->joints, block.items());
}

/// `z:`, `y:` (reference vectors) or `roll:` (rad) of a member in a 3d model.
MemberOrientation readOrientation(const Context& c, const Field& f, const Eigen::Vector3d& axis) {
  MemberOrientation o;
  const auto z = f.get("z"), y = f.get("y"), roll = f.get("roll");
  if (c.deck.dimension == "planar") {
    for (const auto& given : {z, y, roll})
      if (given)
        given->fail("a planar frame's members bend in the x-y plane (local z = global z); "
                    "z, y and roll orient members of 3d models");
    return o;
  }
  if (z && y) y->fail("give either z or y (a reference vector for one local axis), not both");
  if (z) o.zReference = coordinates(c, *z, "a direction", dim::none);
  if (y) o.yReference = coordinates(c, *y, "a direction", dim::none);
  if (roll) o.roll = roll->number(c.evaluator, dim::angle);
  try {
    memberAxes(axis, o);
  } catch (const std::invalid_argument& e) {
    (z ? *z : *y).fail(e.what());
  }
  return o;
}

/// `release: {start: [rz], end: [ry, rz]}`: rotations about the member's local axes.
std::array<std::vector<Dof>, 2> readReleases(const Context& c, const Field& f) {
  std::array<std::vector<Dof>, 2> out;
  f.allowOnly({"start", "end"}, "a member's releases");
  for (int end = 0; end < 2; ++end) {
    auto side = f.get(end == 0 ? "start" : "end");
    if (!side) continue;
    for (const Field& item : side->itemsOrSingle()) {
      const Dof d = c.rotation(item);
      if (std::find(out[end].begin(), out[end].end(), d) != out[end].end())
        item.fail(std::string(dofName(d)) + " is listed twice");
      out[end].push_back(d);
    }
  }
  return out;
}

int memberEnd(Context& c, const Field& f);

/// `offsets: {start: [..], end: [..], axes: global | member}`: rigid arms from the member's
/// joints to its ends. Each end given becomes a joint of its own (MEMBER@start_offset,
/// MEMBER@end_offset) that follows its joint in every dof (a rigid link), and the member runs
/// between the arms' ends; member axes are those of the line between the joints.
void readOffsets(Context& c, const Field& f, const std::string& member, DeckMember& m,
                 const Eigen::Vector3d& axis) {
  f.allowOnly({"start", "end", "axes"}, "a member's offsets");
  const bool inMemberAxes = f.get("axes") && f.require("axes").choice({"global", "member"}) == "member";
  const Eigen::Matrix3d R = memberAxes(axis, m.orientation);  // rows: local axes
  for (int end = 0; end < 2; ++end) {
    const char* key = end == 0 ? "start" : "end";
    auto given = f.get(key);
    if (!given) continue;
    Eigen::Vector3d r = coordinates(c, *given, "an offset", dim::length);
    if (inMemberAxes) r = R.transpose() * r;
    int& joint = end == 0 ? m.from : m.to;
    auto& joints = c.deck.frame->joints;
    const DeckJoint& from = joints[joint];
    DeckJoint arm{member + "@" + key + "_offset", from.x + r, given->place()};
    for (const DeckJoint& other : joints)
      if ((other.x - arm.x).norm() <= 1e-12 * std::max(1.0, arm.x.norm()))
        given->fail("the offset end lies on node '" + other.name + "'");
    c.deck.rigidLinks.push_back({arm.name, from.name, arm.name, {}, given->place()});
    for (Dof d : kAllDofs)
      if (c.deck.dofs.contains(d)) c.deck.rigidLinks.back().dofs.push_back(d);
    c.deck.points.push_back({arm.name, 0, arm.place});
    joint = int(joints.size());
    joints.push_back(std::move(arm));
  }
}

double readMembers(Context& c) {
  const Field block = c.root.require("members");
  TakenNames names;
  double elements = 0;
  for (const Field& f : block.items()) {
    f.allowOnly({"name", "from", "to", "section", "elements", "size", "formulation", "z", "y",
                 "roll", "release", "offsets", "acts"},
                "a member");
    DeckSegment s;
    s.place = f.place();
    const Field nf = f.require("name");
    s.name = nf.name();
    claimName(nf, s.name, names, "a member");
    DeckMember m;
    m.place = f.place();
    m.from = memberEnd(c, f.require("from"));
    m.to = memberEnd(c, f.require("to"));
    if (m.from == m.to) f.require("to").fail("a member joins two different nodes");
    const Eigen::Vector3d axis =
        c.deck.frame->joints[m.to].x - c.deck.frame->joints[m.from].x;
    m.orientation = readOrientation(c, f, axis);
    if (auto offsets = f.get("offsets")) readOffsets(c, *offsets, s.name, m, axis);
    s.length = (c.deck.frame->joints[m.to].x - c.deck.frame->joints[m.from].x).norm();
    if (!(s.length > 0)) f.require("offsets").fail("the offsets leave the member no length");
    readSegmentMesh(c, f, s);
    if (auto release = f.get("release")) m.releases = readReleases(c, *release);
    if (auto acts = f.get("acts")) {
      const std::string way = acts->choice({"both", "tension-only", "compression-only"});
      m.acts = way == "tension-only"       ? MemberAction::tensionOnly
               : way == "compression-only" ? MemberAction::compressionOnly
                                           : MemberAction::both;
      if (m.acts != MemberAction::both && s.elementEstimate() != 1)
        acts->fail("a " + way + " member is one element (a rod between its end nodes, which "
                   "goes slack as a whole): give it elements: 1");
    }
    elements += s.elementEstimate();
    if (!(elements <= kMaxFrameElements))
      f.fail("the frame would have more than " + std::to_string(kMaxFrameElements) +
             " elements; use fewer elements or a larger size");
    c.deck.segments.push_back(std::move(s));
    c.deck.frame->members.push_back(std::move(m));
  }
  if (c.deck.frame->members.empty()) block.fail("a frame needs at least one member");
  return elements;
}

/// The name of the place at `fraction` of member `m`: its joint at either end, otherwise
/// "MEMBER@FRACTION" with every digit the fraction has (two places never share a name).
std::string placeName(const Context& c, int m, double fraction) {
  const DeckMember& member = c.deck.frame->members[m];
  if (fraction <= kEndTolerance) return c.deck.frame->joints[member.from].name;
  if (fraction >= 1 - kEndTolerance) return c.deck.frame->joints[member.to].name;
  return fractionPlaceName(c.deck.segments[m].name, fraction);
}

/// Member and fraction of a place: `member:` with `at:` (fraction of its length from its
/// `from` node, 0 to 1) or `at_length:` (m from that node).
std::pair<int, double> memberPlace(const Context& c, const Field& f,
                                   const std::vector<std::string>& otherKeys) {
  std::vector<std::string> keys{"member", "at", "at_length"};
  keys.insert(keys.end(), otherKeys.begin(), otherKeys.end());
  f.allowOnly(keys, "a place on a member");
  const int m = c.segment(f.require("member"));
  const auto at = f.get("at"), length = f.get("at_length");
  if (at && length) length->fail("give either at (a fraction) or at_length (m), not both");
  if (!at && !length) {
    DeckPlace place = f.place();
    place.field = f.path() + ".at";
    throw DeckError(f.file(), place,
                    "missing required field 'at' (fraction of the member's length from its "
                    "'from' node, 0 to 1; or 'at_length' in m)");
  }
  const double L = c.deck.segments[m].length;
  const double value = (at ? *at : *length).number(c.evaluator, at ? dim::none : dim::length);
  const double fraction = at ? value : value / L;
  if (!(fraction >= 0 && fraction <= 1))
    (at ? *at : *length)
        .fail(at ? "a fraction of the member's length lies in [0, 1], got " + formatNumber(value)
                 : "member '" + c.deck.segments[m].name + "' is " + formatNumber(L) +
                       " m long; at_length lies in [0, " + formatNumber(L) + "], got " +
                       formatNumber(value));
  return {m, fraction};
}

/// The joint a member's `from:` or `to:` names: a node, or a place on a member listed before
/// it, `{member: front, at: 0.5}` (or at_length) or `front@0.5`: its end node, or inside it a
/// joint of its own named "front@0.5", where that member is cut and shares its node.
int memberEnd(Context& c, const Field& f) {
  std::pair<int, double> place{-1, 0};
  if (f.isMap()) {
    place = memberPlace(c, f, {});
  } else if (f.isScalar() && f.text().find('@') != std::string::npos) {
    const std::string text = f.text();
    const std::string host = text.substr(0, text.find('@'));
    const auto& segments = c.deck.segments;
    const auto hostIndex = c.segmentNamed(host);
    std::vector<std::string> names;
    if (!hostIndex)
      for (const DeckSegment& s : segments) names.push_back(s.name);
    if (!hostIndex)
      f.fail("no member named '" + host + "' before this one" + didYouMean(host, names) +
             " (a member may start or end on a member listed before it: " + joinNames(names) +
             ")");
    char* end = nullptr;
    const std::string digits = text.substr(text.find('@') + 1);
    const double fraction = std::strtod(digits.c_str(), &end);
    if (digits.empty() || *end != '\0' || !(fraction >= 0 && fraction <= 1))
      f.fail("expected MEMBER@FRACTION with a fraction of the member's length in [0, 1] (e.g. " +
             host + "@0.5), got '" + text + "'");
    place = {*hostIndex, fraction};
  } else {
    return jointIndex(c, f);
  }
  const auto [m, fraction] = place;
  auto& joints = c.deck.frame->joints;
  const DeckMember& host = c.deck.frame->members[m];
  if (fraction <= kEndTolerance) return host.from;
  if (fraction >= 1 - kEndTolerance) return host.to;
  const std::string name = placeName(c, m, fraction);
  if (const auto j = c.jointNamed(name)) return *j;
  const Eigen::Vector3d x = joints[host.from].x + fraction * (joints[host.to].x - joints[host.from].x);
  c.deck.points.push_back({name, 0, f.place()});
  joints.push_back({name, x, f.place(), m, fraction});
  return int(joints.size()) - 1;
}

/// Registers the place (a point and, inside the member, a station) unless it exists.
void addPlace(Context& c, const std::string& name, int member, double fraction,
              const DeckPlace& place) {
  if (c.pointNamed(name)) return;
  c.deck.points.push_back({name, 0, place});
  c.deck.frame->stations.push_back({name, member, fraction});
}

void readStations(Context& c, TakenNames& pointNames, double elements) {
  auto points = c.root.get("points");
  if (!points || points->isNull()) return;
  for (const Field& f : points->items()) {
    const Field nf = f.require("name");
    const std::string name = nf.name();
    const auto [m, fraction] = memberPlace(c, f, {"name"});
    claimName(nf, name, pointNames, "a point or node");
    c.deck.points.push_back({name, 0, f.place()});
    c.deck.frame->stations.push_back({name, m, fraction});
    if (double(c.deck.frame->stations.size()) + elements > kMaxFrameElements)
      f.fail("too many points: the frame would have more than " + std::to_string(kMaxFrameElements) +
             " elements");
  }
}

/// Every `at:` or `to:` written as `{member: ..., at: ...}` in the attachments and in the
/// analyses' lists becomes a point now.
void collectInlinePlaces(Context& c) {
  auto visitItem = [&](const Field& item) {
    if (!item.isMap()) return;
    for (const char* key : {"at", "to"})
      if (auto place = item.get(key); place && place->isMap()) {
        const auto [m, fraction] = memberPlace(c, *place, {});
        addPlace(c, placeName(c, m, fraction), m, fraction, place->place());
      }
  };
  auto visitList = [&](const std::optional<Field>& list) {
    if (list && list->isList())
      for (const Field& item : list->items()) visitItem(item);
  };
  for (const char* block : {"supports", "springs", "contacts", "masses", "hinges", "loads",
                            "bearings"})
    visitList(c.root.get(block));
  if (auto cases = c.root.get("load_cases"); cases && cases->isList())
    for (const Field& lc : cases->items())
      if (lc.isMap()) visitList(lc.get("loads"));
  if (auto analyses = c.root.get("analyses"); analyses && analyses->isList())
    for (const Field& a : analyses->items())
      if (a.isMap())
        for (const char* list : {"initial", "loads", "record", "unbalance"}) visitList(a.get(list));
}

}  // namespace

void readFrame(Context& c) {
  if (c.deck.dimension == "lateral")
    c.root.require(c.root.has("members") ? "members" : "nodes")
        .fail("a frame is a planar or 3d model (model: {dimension: planar} or 3d); lateral "
              "models are rotors along x (segments:)");
  c.deck.frame.emplace();
  TakenNames pointNames;
  readJoints(c, pointNames);
  const double elements = readMembers(c);
  readStations(c, pointNames, elements);
  collectInlinePlaces(c);
}

std::string fractionPlaceName(const std::string& owner, double fraction) {
  char digits[32];
  std::snprintf(digits, sizeof digits, "%.17g", fraction);
  return owner + "@" + digits;
}

void addMemberStation(Context& c, int member, double fraction, const DeckPlace& place) {
  if (fraction <= kEndTolerance || fraction >= 1 - kEndTolerance) return;
  addPlace(c, placeName(c, member, fraction), member, fraction, place);
}

const DeckPoint& memberPoint(const Context& c, const Field& f) {
  if (!c.deck.frame)
    f.fail("a place on a member needs a frame (nodes: and members:); name a point instead");
  const auto [m, fraction] = memberPlace(c, f, {});
  const std::string name = placeName(c, m, fraction);
  for (const DeckPoint& p : c.deck.points)
    if (p.name == name) return p;
  f.fail("this place on member '" + c.deck.segments[m].name +
         "' is not one beamrotor collected; name it under points: instead");
}

}  // namespace beamrotor::reader
