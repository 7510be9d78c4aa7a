// The reader of `type: moving-load` (StructureKinds.hpp): the path, the wheels, their
// direction and the quantities whose influence lines and envelopes it gives.
#include <algorithm>
#include <cmath>
#include <string>

#include "problems/deck/DeckReader.hpp"
#include "problems/deck/ReaderContext.hpp"
#include "problems/deck/parse/Suggest.hpp"
#include "problems/deck/parse/Units.hpp"
#include "problems/deck/structure/StructureKinds.hpp"

namespace beamrotor {

namespace {

/// `path:` of a frame: members in order, each joining the one before it; its length (m).
double readFramePath(const reader::Context& c, const Field& f, std::vector<std::string>& path) {
  const DeckFrame& frame = *c.deck.frame;
  double length = 0;
  std::vector<int> members;
  for (const Field& item : f.itemsOrSingle()) {
    const int m = c.segment(item);
    if (std::find(members.begin(), members.end(), m) != members.end())
      item.fail("member '" + item.text() + "' is on the path twice");
    if (!members.empty()) {
      const DeckMember& before = frame.members[std::size_t(members.back())];
      const DeckMember& here = frame.members[std::size_t(m)];
      // The joint the path has reached: for the first member, the end it shares with this one.
      std::vector<int> reached{before.from, before.to};
      if (members.size() > 1) {
        const DeckMember& earlier = frame.members[std::size_t(members[members.size() - 2])];
        const bool forward = before.from == earlier.from || before.from == earlier.to;
        reached = {forward ? before.to : before.from};
      }
      const bool joins = std::any_of(reached.begin(), reached.end(),
                                     [&](int j) { return j == here.from || j == here.to; });
      if (!joins)
        item.fail("member '" + item.text() + "' does not join member '" + path.back() +
                  "' where the path reaches it: a path's members follow each other end to end");
    }
    members.push_back(m);
    path.push_back(c.deck.segments[std::size_t(m)].name);
    length += c.deck.segments[std::size_t(m)].length;
  }
  if (path.empty()) f.fail("a path needs at least one member");
  return length;
}

}  // namespace

void MovingLoadSpec::read(const reader::Context& c, const Field& f) {
  f.allowOnly({"type", "name", "path", "direction", "wheels", "quantities", "deck_loads",
               "field_envelopes"},
              "a moving-load analysis");
  if (auto d = f.get("deck_loads")) deckLoads = d->boolean();
  if (auto e = f.get("field_envelopes")) fieldEnvelopes = e->boolean();
  place = f.place();
  const Deck& deck = c.deck;
  if (!deck.contacts.empty())
    f.fail("influence lines superpose unit loads: a deck with contacts is not linear; remove them");
  if (deck.segments.empty()) f.fail("a moving load needs beams to move along");
  for (const DeckSupport& s : deck.supports)
    for (const auto& [d, value] : s.dofs)
      if (value != 0)
        f.fail("influence lines are of a unit load alone: support '" + s.name +
               "' prescribes a nonzero value, which every unit load would repeat");
  if (deck.frame) {
    pathLength = readFramePath(c, f.require("path"), path);
  } else {
    if (auto p = f.get("path"))
      p->fail("a line's moving load crosses the whole line: give path: only in a frame");
    for (const DeckSegment& s : deck.segments) pathLength += s.length;
  }

  // The lines are exact on Euler-Bernoulli beams whose ends keep their rotations (a hinge on a
  // frame's path that only the mesh reveals is refused when the analysis runs).
  for (const DeckSegment& s : deck.segments) {
    const bool onPath = path.empty() || std::find(path.begin(), path.end(), s.name) != path.end();
    if (!onPath) continue;
    if (s.options.theory != BeamTheory::eulerBernoulli)
      f.fail("a moving load's influence lines are exact on Euler-Bernoulli beams; " +
             (s.name.empty() ? std::string("a segment") : "'" + s.name + "'") +
             " on its path has another formulation (set formulation: euler-bernoulli)");
  }
  if (deck.frame)
    for (std::size_t m = 0; m < deck.frame->members.size(); ++m) {
      const DeckMember& member = deck.frame->members[m];
      const std::string& name = deck.segments[m].name;
      if (std::find(path.begin(), path.end(), name) != path.end() &&
          (!member.releases[0].empty() || !member.releases[1].empty()))
        f.fail("member '" + name + "' on the path releases an end: a moving load's path holds "
               "no hinges (its elements' nodal loads would not be the beam's own)");
    }
  // A frame's `hinges:` entry releases every member end at its point: one at a path
  // member's end, at a joint on it or at a station along it releases the path.
  if (deck.frame) {
    const DeckFrame& frame = *deck.frame;
    const auto onPath = [&](int member) {
      return member >= 0 &&
             std::find(path.begin(), path.end(), deck.segments[std::size_t(member)].name) !=
                 path.end();
    };
    for (const DeckHinge& h : deck.hinges) {
      bool released = false;
      for (std::size_t j = 0; j < frame.joints.size(); ++j) {
        if (frame.joints[j].name != h.point) continue;
        released = released || onPath(frame.joints[j].member);
        for (std::size_t m = 0; m < frame.members.size(); ++m)
          if ((frame.members[m].from == int(j) || frame.members[m].to == int(j)) && onPath(int(m)))
            released = true;
      }
      for (const MemberStation& st : frame.stations)
        if (st.name == h.point && onPath(st.member)) released = true;
      if (released)
        f.require("path").fail("the hinge at '" + h.point + "' releases a member end on the path: a moving "
               "load's path holds no hinges (its elements' nodal loads would not be the beam's "
               "own)");
    }
  }
  if (!deck.frame && !deck.hinges.empty())
    f.fail("the line has a hinge (at '" + deck.hinges.front().point +
           "'): a moving load's path holds no hinges (its elements' nodal loads would not be "
           "the beam's own)");

  if (auto d = f.get("direction")) {
    const std::vector<Field> items = d->items();
    if (items.size() != 3) d->fail("a direction is three numbers [x, y, z]");
    for (std::size_t k = 0; k < 3; ++k) direction[k] = items[k].number(c.evaluator, dim::none);
    const double norm = std::hypot(direction[0], direction[1], direction[2]);
    if (!(norm > 0)) d->fail("a direction needs a nonzero length");
    if (deck.dimension == "planar" && direction[2] != 0)
      d->fail("a planar model carries loads in its x-y plane: give z = 0");
    for (double& x : direction) x /= norm;
  }

  const Field wheelList = f.require("wheels");
  for (const Field& w : wheelList.items()) {
    w.allowOnly({"force", "offset"}, "a wheel");
    Wheel wheel;
    wheel.force = w.require("force").number(c.evaluator, dim::force);
    if (wheel.force == 0) w.require("force").fail("a wheel's force must not be zero");
    if (auto o = w.get("offset")) {
      wheel.offset = o->nonNegative(c.evaluator, dim::length);
      if (wheel.offset >= pathLength)
        o->fail("the wheel is never on the path together with the first wheel: its offset " +
                formatNumber(wheel.offset) + " m reaches past the path's length " +
                formatNumber(pathLength) + " m");
    }
    wheels.push_back(wheel);
  }
  if (wheels.empty()) wheelList.fail("a moving load needs at least one wheel");

  const Field list = f.require("quantities");
  for (const Field& item : list.itemsOrSingle()) {
    Quantity q;
    try {
      q = parseQuantity(item.text());
    } catch (const std::invalid_argument& e) {
      item.fail(e.what());
    }
    if (q.kind == Quantity::Kind::reaction) {
      reader::requireReactionTarget(deck, q, item);
    } else if (q.kind == Quantity::Kind::displacement || q.kind == Quantity::Kind::resultantAt) {
      if (!c.pointNamed(q.target) && !c.jointNamed(q.target)) {
        std::vector<std::string> names;
        for (const DeckPoint& p : deck.points) names.push_back(p.name);
        if (deck.frame)
          for (const DeckJoint& j : deck.frame->joints) names.push_back(j.name);
        item.fail("no point named '" + q.target + "'" + didYouMean(q.target, names));
      }
      if (q.kind == Quantity::Kind::displacement && q.side != Quantity::Side::node)
        item.fail("a moving load's displacement is a point's own, not a side's rotation");
      if (q.kind == Quantity::Kind::displacement && !deck.dofs.contains(q.dof))
        item.fail(std::string(dofName(q.dof)) + " is not a dof of a " + deck.dimension +
                  " model (" + c.carriedNames() + ")");
    } else {
      item.fail("'" + q.text + "' is not linear in the load: a moving load gives the influence "
                "lines of reactions, displacements and resultants at points");
    }
    for (const Quantity& earlier : quantities)
      if (earlier.text == q.text) item.fail("'" + q.text + "' is listed twice");
    quantities.push_back(q);
  }
  if (quantities.empty()) list.fail("name at least one quantity");
}

}  // namespace beamrotor
