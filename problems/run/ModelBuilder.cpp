#include "problems/run/ModelBuilder.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <memory>
#include <vector>

#include "elements/Bearing.hpp"
#include "elements/BearingOnPedestal.hpp"
#include "elements/PointInertia.hpp"
#include "elements/Spring.hpp"
#include "elements/TiltingPadFilm.hpp"
#include "elements/TiltingPadWhirl.hpp"
#include "elements/TurnedBearing.hpp"
#include "elements/WhirlTable.hpp"
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

/// A beam of the model and the deck segment it lies in (a frame's member).
struct BeamInSegment {
  int element = -1;  ///< index into Model::elements()
  int segment = -1;
};

/// Every beam of the model built from the deck with its segment: a frame's members are its
/// segments in deck order; a line's beams run along x from 0, one segment after the other, so
/// a beam's midpoint tells its segment.
std::vector<BeamInSegment> beamsInSegments(const Deck& deck, const Model& model) {
  std::vector<BeamInSegment> out;
  if (deck.frame) {
    for (std::size_t m = 0; m < model.members().size(); ++m)
      for (int e : model.members()[m].second) out.push_back({e, int(m)});
    return out;
  }
  std::vector<double> ends;
  double x = 0;
  for (const DeckSegment& s : deck.segments) ends.push_back(x += s.length);
  for (int e = 0; e < int(model.elements().size()); ++e) {
    const LineElement* line = asLine(model.elements()[e]);
    if (!line) continue;
    const auto [a, b] = line->endNodes();
    const double mid = 0.5 * (model.nodes()[a].x() + model.nodes()[b].x());
    const auto it = std::upper_bound(ends.begin(), ends.end(), mid);
    out.push_back({e, std::min(int(it - ends.begin()), int(ends.size()) - 1)});
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
Eigen::Vector3d distributedLoadAt(const DeckLoad& l, const LineElement& beam, const SegmentAxis& axis,
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

/// The line: segments cut at every named point.
void addLine(const Deck& deck, Model& model) {
  LineSpec spec;
  spec.dofs = deck.dofs;
  for (const DeckSegment& s : deck.segments)
    spec.segments.push_back({s.length, s.section, s.elements, s.size, s.options});
  for (const DeckPoint& p : deck.points) spec.points.push_back({p.name, p.at});
  at(deck, deck.segments.front().place, [&] { buildLine(model, spec); });
}

/// The frame: joints, members cut at their stations; each member named in the model.
void addFrame(const Deck& deck, Model& model) {
  const DeckFrame& frame = *deck.frame;
  FrameSpec spec;
  spec.dofs = deck.dofs;
  for (const DeckJoint& j : frame.joints) spec.joints.push_back({j.name, j.x, j.member, j.fraction});
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
  std::map<const Element*, int> index;
  for (std::size_t e = 0; e < model.elements().size(); ++e) index[model.elements()[e].get()] = int(e);
  for (std::size_t m = 0; m < mesh.memberBeams.size(); ++m) {
    std::vector<int> elements;
    for (Beam* beam : mesh.memberBeams[m]) elements.push_back(index.at(beam));
    model.addMember(deck.segments[m].name, std::move(elements));
  }
}

/// The span loads (distributed loads, self-weight, temperature changes) of `loads` acting on
/// each segment, in the order of `loads`: one pass over the loads, not one per beam (a frame
/// with a floor load on each of its 10^4 beams has 10^4 loads).
std::vector<std::vector<const DeckLoad*>> spanLoadsBySegment(const Deck& deck,
                                                             const std::vector<DeckLoad>& loads) {
  std::vector<std::vector<const DeckLoad*>> out(deck.segments.size());
  for (const DeckLoad& l : loads) {
    if (l.kind != DeckLoad::Kind::distributed && l.kind != DeckLoad::Kind::selfWeight &&
        l.kind != DeckLoad::Kind::temperature)
      continue;
    if (l.segments.empty()) {
      for (auto& acting : out) acting.push_back(&l);
      continue;
    }
    for (int segment : l.segments) {
      std::vector<const DeckLoad*>& acting = out[std::size_t(segment)];
      if (acting.empty() || acting.back() != &l) acting.push_back(&l);  // a segment named twice
    }
  }
  return out;
}

/// The span load `acting` (one segment's, spanLoadsBySegment) puts on `beam` of segment
/// `segment` (N/m, global frame, at its start and end node): summed in the deck's order.
std::array<Eigen::Vector3d, 2> spanLoadOn(const Deck& deck, const std::vector<const DeckLoad*>& acting,
                                          const Model& model, const LineElement& beam,
                                          int segment) {
  std::array<Eigen::Vector3d, 2> q{Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
  if (acting.empty()) return q;
  const SegmentAxis axis = segmentAxis(deck, segment);
  std::array<double, 2> span;  // the beam's ends as fractions of its segment's length
  for (int end = 0; end < 2; ++end)
    span[end] =
        (model.nodes()[beam.endNodes()[end]] - axis.start).dot(axis.direction) / axis.length;
  for (const DeckLoad* l : acting) {
    if (l->kind == DeckLoad::Kind::distributed)
      for (int end = 0; end < 2; ++end) q[end] += distributedLoadAt(*l, beam, axis, span, end);
    if (l->kind == DeckLoad::Kind::selfWeight)
      for (Eigen::Vector3d& qe : q) qe.y() -= beam.section().rhoA() * l->g;
  }
  return q;
}

/// The strain the temperature loads among `acting` (one segment's, spanLoadsBySegment) impose
/// on `beam` (local frame, laid out as ElementSpanLoad::strain), summed.
Eigen::Vector3d imposedStrainOn(const std::vector<const DeckLoad*>& acting, const LineElement& beam) {
  Eigen::Vector3d strain = Eigen::Vector3d::Zero();
  for (const DeckLoad* l : acting)
    if (l->kind == DeckLoad::Kind::temperature)
      strain += thermalStrain(beam.section(), l->dT, l->dTy, l->dTz);
  return strain;
}

/// The point loads of `loads` at their nodes.
std::vector<NodalLoad> pointLoads(const Deck& deck, const Model& model,
                                  const std::vector<DeckLoad>& loads) {
  std::vector<NodalLoad> out;
  for (const DeckLoad& l : loads)
    if (l.kind == DeckLoad::Kind::point)
      at(deck, l.place, [&] {
        for (const auto& [d, value] : l.components) out.push_back({model.node(l.point), d, value});
      });
  return out;
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

std::shared_ptr<Model> buildModel(const Deck& deck, const std::vector<bool>& slackMembers) {
  if (needsJournalLoads(deck)) return buildModel(withJournalLoads(deck));
  auto model = std::make_shared<Model>();
  if (deck.segments.empty()) {
    addPointNodes(deck, *model);
    addAttachments(deck, model.get());
    return model;
  }

  // 1. The beams: a line of segments cut at every named point, or a frame's members.
  if (deck.frame)
    addFrame(deck, *model);
  else
    addLine(deck, *model);
  std::vector<Beam*> beams;
  const auto spanLoads = spanLoadsBySegment(deck, deck.loads);
  for (const BeamInSegment& b : beamsInSegments(deck, *model)) {
    Beam* beam = dynamic_cast<Beam*>(model->elements()[b.element].get());
    if (!beam) throw std::logic_error("a deck's line element is not a beam");
    beams.push_back(beam);

    // 2. Distributed loads and self-weight, summed per beam (a beam holds one load varying
    //    linearly from its start to its end), and the strain temperature changes impose.
    const std::vector<const DeckLoad*>& acting = spanLoads[std::size_t(b.segment)];
    const std::array<Eigen::Vector3d, 2> q = spanLoadOn(deck, acting, *model, *beam, b.segment);
    if (!q[0].isZero() || !q[1].isZero()) beam->setDistributedLoad(q[0], q[1]);
    const Eigen::Vector3d strain = imposedStrainOn(acting, *beam);
    if (!strain.isZero()) beam->setImposedStrain(strain);
    beam->setAxialPreload(deck.segments[b.segment].axialForce);
    if (std::size_t(b.segment) < slackMembers.size() && slackMembers[std::size_t(b.segment)])
      beam->setSlack(true);
  }

  // 3. Hinges: release the rotations of every beam end at the point; a rotation released on
  //    all sides leaves the node without that dof.
  for (const DeckHinge& h : deck.hinges)
    at(deck, h.place, [&] {
      const int node = model->node(h.point);
      for (Beam* beam : beams)
        for (int end = 0; end < 2; ++end)
          if (beam->endNodes()[end] == node)
            for (Dof d : h.released) beam->release(end, d);
    });

  // 4. Supports, springs, masses and point loads at their nodes.
  addAttachments(deck, model.get());
  return model;
}

namespace {

/// The bearing on its pedestal: a housing node at the bearing's point (uy, uz free, every
/// other dof fixed), the pedestal's mass there and its springs to the ground, and the bearing
/// between journal and housing.
/// The bearing's coefficients by whirl as well, turned by its load angle: a table by whirl
/// frequency, or tilting pads condensed at each mode's eigenvalue (whirl_coefficients:
/// each-mode); null for neither.
std::shared_ptr<const WhirlCoefficients> whirlCoefficientsOf(const DeckBearing& b) {
  std::shared_ptr<const WhirlCoefficients> whirl;
  if (!b.whirls.empty())
    whirl = std::make_shared<WhirlTable>(b.speeds, b.whirls, b.whirlRows);
  else if (b.eachModesWhirl && !b.padPoints.empty())
    whirl = std::make_shared<TiltingPadWhirl>(b.padPoints);
  if (whirl && b.loadAngle != 0) whirl = std::make_shared<TurnedWhirl>(whirl, b.loadAngle);
  return whirl;
}

void addPedestal(const Deck& deck, const DeckBearing& b, std::vector<BearingCoefficients> table,
                 Model* model) {
  const DeckPedestal& p = *b.pedestal;
  const int journal = model->node(b.point);
  const Eigen::Vector3d x = model->nodes()[journal];
  const int housing = model->addNode(x);
  Support fixed{b.name + " pedestal", housing, {}};
  for (Dof d : kAllDofs)
    if (deck.dofs.contains(d) && d != Dof::uy && d != Dof::uz) fixed.dofs.push_back({d, 0});
  if (!fixed.dofs.empty()) model->addSupport(std::move(fixed));
  if (p.m > 0) model->add<PointInertia>(housing, DofSet{Dof::uy, Dof::uz}, p.m);
  model->add<Spring>(NodeDof{housing, Dof::uy}, p.kyy, p.cyy);
  model->add<Spring>(NodeDof{housing, Dof::uz}, p.kzz, p.czz);
  std::vector<double> speeds = b.speeds.empty() ? std::vector<double>{0.0} : b.speeds;
  auto& bearing =
      model->add<BearingOnPedestal>(journal, housing, std::move(speeds), std::move(table));
  bearing.setWhirlCoefficients(whirlCoefficientsOf(b));
}

/// A tilting-pad bearing with its pads' tilts kept: a node per pad loaded at some table speed
/// (every pad with everyPadTilt; at the journal, its rx the pad's tilt, every other dof absent)
/// and that pad's film between journal and pad (elements/TiltingPadFilm.hpp); no condensed
/// Bearing element.
void addPadTilts(const DeckBearing& b, Model* model) {
  const int journal = model->node(b.point);
  const Eigen::Vector3d x = model->nodes()[journal];
  auto points = std::make_shared<const std::vector<TiltingPadPoint>>(b.padPoints);
  for (int pad = 0; pad < int(b.padPoints.front().pads.size()); ++pad) {
    if (!b.everyPadTilt && !padEverLoaded(*points, pad)) continue;
    const int node = model->addNode(x);
    model->add<TiltingPadFilm>(journal, node, points, pad, b.loadAngle, *b.padInertia);
  }
}

void addAttachments(const Deck& deck, Model* model) {
  for (const DeckSupport& s : deck.supports)
    at(deck, s.place, [&] {
      Support support{s.name, model->node(s.point), {}};
      for (const auto& [d, value] : s.dofs) support.dofs.push_back({d, value});
      model->addSupport(std::move(support));
    });
  for (std::size_t i = 0; i < deck.springs.size(); ++i) {
    const DeckSpring& s = deck.springs[i];
    at(deck, s.place, [&] {
      const NodeDof a{model->node(s.point), s.dof};
      if (s.toPoint.empty())
        model->add<Spring>(a, s.k, s.c);
      else
        model->add<Spring>(a, NodeDof{model->node(s.toPoint), s.dof}, s.k, s.c);
      model->nameElement(springName(deck, i), int(model->elements().size()) - 1);
    });
  }
  for (const DeckContact& k : deck.contacts)
    at(deck, k.place, [&] {
      model->addContact({k.name, model->node(k.point), k.dof, k.lower, k.upper});
    });
  for (const DeckRigidLink& l : deck.rigidLinks)
    at(deck, l.place, [&] {
      model->addRigidTie({l.name, model->node(l.master), model->node(l.slave), l.dofs});
    });
  for (const DeckMass& m : deck.masses)
    at(deck, m.place, [&] {
      const DofSet dofs = deck.segments.empty() ? inertialDofs(m, deck.dofs) : deck.dofs;
      model->add<PointInertia>(model->node(m.point), dofs, m.m, m.Jp, m.Jd,
                               Eigen::Vector3d::UnitX());
    });
  for (const DeckBearing& b : deck.rotor.bearings)
    at(deck, b.place, [&] {
      std::vector<BearingCoefficients> table;
      for (const BearingCoefficients& row : b.table)
        table.push_back(turnedCoefficients(row, b.loadAngle));
      if (b.pedestal)  // the bearing acts between journal and housing: its force as it is
        addPedestal(deck, b, std::move(table), model);
      else if (b.padInertia && !b.padPoints.empty())
        addPadTilts(b, model);
      else if (b.speeds.empty())
        model->add<Bearing>(model->node(b.point), table.front());
      else
        model->add<Bearing>(model->node(b.point), b.speeds, std::move(table))
            .setWhirlCoefficients(whirlCoefficientsOf(b));
      model->nameElement(b.name, int(model->elements().size()) - 1);
    });
  for (const NodalLoad& l : pointLoads(deck, *model, deck.loads)) model->addLoad(l);
}

}  // namespace

Loading loadingOf(const Deck& deck, const Model& model, const std::vector<DeckLoad>& loads) {
  std::vector<std::pair<int, ElementSpanLoad>> span;
  const auto spanLoads = spanLoadsBySegment(deck, loads);
  for (const BeamInSegment& b : beamsInSegments(deck, model)) {
    const LineElement& line = *asLine(model.elements()[b.element]);
    const std::vector<const DeckLoad*>& acting = spanLoads[std::size_t(b.segment)];
    const std::array<Eigen::Vector3d, 2> q = spanLoadOn(deck, acting, model, line, b.segment);
    ElementSpanLoad load = line.spanLoadOf(q[0], q[1]);
    load.strain = imposedStrainOn(acting, line);
    if (!load.isZero()) span.emplace_back(b.element, load);
  }
  return Loading(pointLoads(deck, model, loads), std::move(span));
}

}  // namespace beamrotor
