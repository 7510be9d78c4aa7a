#include "problems/run/ModelBuilder.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <vector>

#include "elements/Bearing.hpp"
#include "elements/PointInertia.hpp"
#include "elements/Spring.hpp"
#include "meshes/FrameBuilder.hpp"
#include "meshes/LineBuilder.hpp"
#include "problems/run/JournalGravityLoads.hpp"

namespace beamrotor {

namespace {

/// Runs one building step; the core's std::exceptions become a DeckError at `place`.
template <class Step>
void at(const Deck& deck, const DeckPlace& place, Step&& step) {
  try {
    step();
  } catch (const DeckError&) {
    throw;
  } catch (const std::exception& e) {
    throw DeckError(deck.path, place, e.what());
  }
}

/// Index of the segment each beam of the line lies in (beams run start to end, one after the
/// other, so a beam's midpoint station identifies its segment).
std::vector<int> segmentOfBeams(const Deck& deck, const Line& line) {
  std::vector<double> ends;
  double x = 0;
  for (const DeckSegment& s : deck.segments) ends.push_back(x += s.length);
  std::vector<int> out;
  for (std::size_t b = 0; b < line.beams.size(); ++b) {
    const double mid = 0.5 * (line.stations[b] + line.stations[b + 1]);
    const auto it = std::upper_bound(ends.begin(), ends.end(), mid);
    out.push_back(std::min(int(it - ends.begin()), int(ends.size()) - 1));
  }
  return out;
}

/// Where a segment (a frame's member) lies: its start, unit direction and length.
struct SegmentAxis {
  Eigen::Vector3d start, direction;
  double length = 0;
};

SegmentAxis segmentAxis(const Deck& deck, int segment) {
  const double length = deck.segments[segment].length;
  if (deck.frame) {
    const DeckMember& m = deck.frame->members[segment];
    const Eigen::Vector3d a = deck.frame->joints[m.from].x, b = deck.frame->joints[m.to].x;
    return {a, (b - a) / length, length};
  }
  double x = 0;
  for (int k = 0; k < segment; ++k) x += deck.segments[k].length;
  return {Eigen::Vector3d(x, 0, 0), Eigen::Vector3d::UnitX(), length};
}

/// A distributed load's value (N/m, global) at end `end` of a beam spanning fractions `span`
/// of its segment: zero outside the loaded part (whose ends are nodes, so a beam lies wholly
/// inside or outside it), linear from q at `from` to qEnd at `to` inside; turned from member
/// axes, or scaled per projected length (component k by the length of the segment's
/// projection across direction k, sqrt(1 - e_k^2) per unit length).
Eigen::Vector3d distributedLoadAt(const DeckLoad& l, const Beam& beam, const SegmentAxis& axis,
                                  const std::array<double, 2>& span, int end) {
  constexpr double kInside = 1e-9;  // fractions: a node at the part's end, up to round-off
  const double middle = 0.5 * (span[0] + span[1]);
  if (middle < l.from - kInside || middle > l.to + kInside) return Eigen::Vector3d::Zero();
  const double t = std::clamp((span[end] - l.from) / (l.to - l.from), 0.0, 1.0);
  Eigen::Vector3d q = (1 - t) * l.q + t * l.qEnd;
  if (l.inMemberAxes) return beam.localAxes().transpose() * q;
  if (l.perProjectedLength)
    for (int k = 0; k < 3; ++k)
      q[k] *= std::sqrt(std::max(0.0, 1 - axis.direction[k] * axis.direction[k]));
  return q;
}

/// Supports, springs, contacts, masses and point loads at their nodes (model: not null).
void addAttachments(const Deck& deck, Model* model);

/// The beams of the model in order and the deck segment (a frame's member) of each.
struct BuiltBeams {
  std::vector<Beam*> beams;
  std::vector<int> segmentOf;
};

/// The line: segments cut at every named point.
BuiltBeams addLine(const Deck& deck, Model& model) {
  LineSpec spec;
  spec.dofs = deck.dofs;
  for (const DeckSegment& s : deck.segments)
    spec.segments.push_back({s.length, s.section, s.elements, s.size, s.options});
  for (const DeckPoint& p : deck.points) spec.points.push_back({p.name, p.at});
  Line line;
  at(deck, deck.segments.front().place, [&] { line = buildLine(model, spec); });
  return {line.beams, segmentOfBeams(deck, line)};
}

/// The frame: joints, members cut at their stations; each member named in the model.
BuiltBeams addFrame(const Deck& deck, Model& model) {
  const DeckFrame& frame = *deck.frame;
  FrameSpec spec;
  spec.dofs = deck.dofs;
  for (const DeckJoint& j : frame.joints) spec.joints.push_back({j.name, j.x});
  for (std::size_t m = 0; m < frame.members.size(); ++m) {
    const DeckSegment& s = deck.segments[m];
    const DeckMember& member = frame.members[m];
    spec.members.push_back({member.from, member.to,
                            Segment{s.length, s.section, s.elements, s.size, s.options},
                            member.orientation, member.releases});
  }
  spec.stations = frame.stations;
  FrameMesh mesh;
  at(deck, frame.members.front().place, [&] { mesh = buildFrame(model, spec); });
  BuiltBeams out;
  std::map<const Element*, int> index;
  for (std::size_t e = 0; e < model.elements().size(); ++e) index[model.elements()[e].get()] = int(e);
  for (std::size_t m = 0; m < mesh.memberBeams.size(); ++m) {
    std::vector<int> elements;
    for (Beam* beam : mesh.memberBeams[m]) {
      out.beams.push_back(beam);
      out.segmentOf.push_back(int(m));
      elements.push_back(index.at(beam));
    }
    model.addMember(deck.segments[m].name, std::move(elements));
  }
  return out;
}

bool acts(const DeckLoad& l, int segment) {
  return l.segments.empty() ||
         std::find(l.segments.begin(), l.segments.end(), segment) != l.segments.end();
}

/// The dofs on which a body has inertia: translations with m, rotations with Jp (about the
/// axis x) or Jd. A model without beams carries only these, so no dof is left without mass.
DofSet inertialDofs(const DeckMass& m, const DofSet& carried) {
  DofSet out;
  for (Dof d : kAllDofs) {
    const double inertia = !isRotation(d) ? m.m : d == Dof::rx ? m.Jp : m.Jd;
    if (carried.contains(d) && inertia > 0) out = out.with(d);
  }
  return out;
}

/// Nodes at the points of a model without beams, at (x, 0, 0).
void addPointNodes(const Deck& deck, Model& model) {
  for (const DeckPoint& p : deck.points)
    at(deck, p.place, [&] { model.nameNode(p.name, model.addNode({p.at, 0, 0})); });
}

}  // namespace

std::shared_ptr<Model> buildModel(const Deck& deck) {
  if (needsJournalLoads(deck)) return buildModel(withJournalLoads(deck));
  auto model = std::make_shared<Model>();
  if (deck.segments.empty()) {
    addPointNodes(deck, *model);
    addAttachments(deck, model.get());
    return model;
  }

  // 1. The beams: a line of segments cut at every named point, or a frame's members.
  const BuiltBeams beams = deck.frame ? addFrame(deck, *model) : addLine(deck, *model);

  // 2. Distributed loads and self-weight, summed per beam (a beam holds one load varying
  //    linearly from its start to its end).
  for (std::size_t b = 0; b < beams.beams.size(); ++b) {
    Beam& beam = *beams.beams[b];
    const int segment = beams.segmentOf[b];
    const SegmentAxis axis = segmentAxis(deck, segment);
    std::array<double, 2> span;  // the beam's ends as fractions of its segment's length
    for (int end = 0; end < 2; ++end)
      span[end] = (model->nodes()[beam.endNodes()[end]] - axis.start).dot(axis.direction) /
                  axis.length;
    std::array<Eigen::Vector3d, 2> q{Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
    for (const DeckLoad& l : deck.loads) {
      if (!acts(l, segment)) continue;
      if (l.kind == DeckLoad::Kind::distributed)
        for (int end = 0; end < 2; ++end) q[end] += distributedLoadAt(l, beam, axis, span, end);
      if (l.kind == DeckLoad::Kind::selfWeight)
        for (Eigen::Vector3d& qe : q) qe.y() -= beam.section().rhoA() * l.g;
    }
    if (!q[0].isZero() || !q[1].isZero()) beam.setDistributedLoad(q[0], q[1]);
    beam.setAxialPreload(deck.segments[segment].axialForce);
  }

  // 3. Hinges: release the rotations of every beam end at the point; a rotation released on
  //    all sides leaves the node without that dof.
  for (const DeckHinge& h : deck.hinges)
    at(deck, h.place, [&] {
      const int node = model->node(h.point);
      for (Beam* beam : beams.beams)
        for (int end = 0; end < 2; ++end)
          if (beam->endNodes()[end] == node)
            for (Dof d : h.released) beam->release(end, d);
    });

  // 4. Supports, springs, masses and point loads at their nodes.
  addAttachments(deck, model.get());
  return model;
}

namespace {

void addAttachments(const Deck& deck, Model* model) {
  for (const DeckSupport& s : deck.supports)
    at(deck, s.place, [&] {
      Support support{s.name, model->node(s.point), {}};
      for (const auto& [d, value] : s.dofs) support.dofs.push_back({d, value});
      model->addSupport(std::move(support));
    });
  for (const DeckSpring& s : deck.springs)
    at(deck, s.place, [&] {
      const NodeDof a{model->node(s.point), s.dof};
      if (s.toPoint.empty())
        model->add<Spring>(a, s.k, s.c);
      else
        model->add<Spring>(a, NodeDof{model->node(s.toPoint), s.dof}, s.k, s.c);
    });
  for (const DeckContact& k : deck.contacts)
    at(deck, k.place, [&] {
      model->addContact({k.name, model->node(k.point), k.dof, k.lower, k.upper});
    });
  for (const DeckMass& m : deck.masses)
    at(deck, m.place, [&] {
      const DofSet dofs = deck.segments.empty() ? inertialDofs(m, deck.dofs) : deck.dofs;
      model->add<PointInertia>(model->node(m.point), dofs, m.m, m.Jp, m.Jd,
                               Eigen::Vector3d::UnitX());
    });
  for (const DeckBearing& b : deck.rotor.bearings)
    at(deck, b.place, [&] {
      if (b.speeds.empty())
        model->add<Bearing>(model->node(b.point), b.table.front());
      else
        model->add<Bearing>(model->node(b.point), b.speeds, b.table);
    });
  for (const DeckLoad& l : deck.loads)
    if (l.kind == DeckLoad::Kind::point)
      at(deck, l.place, [&] {
        for (const auto& [d, value] : l.components)
          model->addLoad({model->node(l.point), d, value});
      });
}

}  // namespace

}  // namespace beamrotor
