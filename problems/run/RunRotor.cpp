// The rotor analyses of a deck (see RunRotor.hpp), one runner per kind: damped modes at one
// speed, the Campbell diagram and its critical speeds, the unbalance response, the rigid body
// on two springs against the two-dof closed form of problems/scenes/README.md section 2, the
// frequency response, the critical-speed map and the bearing loads.
#include "problems/run/RunRotor.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <variant>

#include "elements/Bearing.hpp"
#include "elements/PointInertia.hpp"
#include "elements/BearingOnPedestal.hpp"
#include "elements/FiniteJournalFilm.hpp"
#include "elements/ShortJournalFilm.hpp"
#include "elements/Spring.hpp"
#include "elements/TiltingPadFilm.hpp"
#include "elements/TiltingPadJournalFilm.hpp"
#include "fem/assembly/ParallelParts.hpp"
#include "fem/rotor/CriticalSpeedMap.hpp"
#include "fem/rotor/CriticalSpeedRefinement.hpp"
#include "fem/rotor/RotorCampbell.hpp"
#include "fem/rotor/RotorFrequencyResponse.hpp"
#include "fem/rotor/RotorModes.hpp"
#include "fem/rotor/RotorStability.hpp"
#include "fem/rotor/RotorUnbalance.hpp"
#include "fem/rotor/UnbalancePeaks.hpp"
#include "fem/timing/Stopwatch.hpp"
#include "problems/run/CampbellWarnings.hpp"
#include "problems/run/ModelBuilder.hpp"
#include "problems/run/Overloaded.hpp"

namespace beamrotor {

namespace {

std::vector<JournalBearingCurve> journalCurves(const Deck& deck) {
  std::vector<JournalBearingCurve> out;
  for (const DeckBearing& b : deck.rotor.bearings) {
    if (!b.journal || b.journal->load == 0) continue;  // a centred journal: no eccentricity
    JournalBearingCurve curve{b.name, b.tiltingPads ? "tilting-pad" : "plain-journal",
                              *b.journal, b.speeds, {}, {}, {}, b.table};
    for (std::size_t i = 0; i < b.speeds.size(); ++i) {
      curve.eccentricity.push_back(b.journalPoints.at(i).eccentricity);
      curve.attitude.push_back(b.journalPoints.at(i).attitude);
      curve.sommerfeld.push_back(b.journal->sommerfeld(b.speeds[i]));
    }
    out.push_back(std::move(curve));
  }
  return out;
}

/// The operating range of the deck's first unbalance analysis that gives one.
std::optional<OperatingRange> deckOperatingRange(const Deck& deck) {
  for (const DeckAnalysis& a : deck.analyses)
    if (const auto* unbalance = a.as<UnbalanceSpec>(); unbalance && unbalance->rotor.operating)
      return unbalance->rotor.operating;
  return std::nullopt;
}

/// The deck's bearings whose coefficients change with speed: their kxx and kyy.
std::vector<BearingStiffnessCurve> bearingStiffnessCurves(const Deck& deck) {
  std::vector<BearingStiffnessCurve> out;
  for (const DeckBearing& b : deck.rotor.bearings) {
    if (b.speeds.empty()) continue;
    BearingStiffnessCurve curve{b.name, b.speeds, {}, {}, {}, {}};
    for (const BearingCoefficients& k : b.table) {
      curve.kxx.push_back(k.kyy);
      curve.kyy.push_back(k.kzz);
    }
    out.push_back(std::move(curve));
  }
  return out;
}

/// The deck's model rebuilt with `change` made to every bearing `which` picks; null when it
/// picks none (the deck's own model stands).
template <class Which, class Change>
std::shared_ptr<const Model> modelWithBearings(const Deck& deck, Which which, Change change) {
  const auto& bearings = deck.rotor.bearings;
  if (std::none_of(bearings.begin(), bearings.end(), which)) return nullptr;
  Deck changed = deck;
  for (DeckBearing& b : changed.rotor.bearings)
    if (which(b)) change(b);
  return buildModel(changed);
}

/// For the analyses that put supports of their own in place of every bearing (pinned, or a
/// swept stiffness): the model `pad_tilts: condensed` builds, each bearing one element on its
/// journal, when a bearing keeps its pads' tilts as dofs (the pads do not enter those
/// analyses, and the answers are the condensed deck's to the bit); null otherwise. The deck's
/// journal loads are already resolved (runDeck), so no bearing table is computed again.
std::shared_ptr<const Model> padsCondensedModel(const Deck& deck) {
  return modelWithBearings(
      deck, [](const DeckBearing& b) { return b.padInertia.has_value(); },
      [](DeckBearing& b) { b.padInertia.reset(); });
}

RotorOptions optionsOf(const Deck& deck, const RotorFamily& s) {
  RotorOptions o;
  o.modes = s.modes;
  o.shift = s.shift;
  o.damping = deck.rotor.damping;
  return o;
}

/// Grounded stiffness on uy at a node at rest: springs on uy and bearings' kyy (N/m), a
/// bearing whose pads are dofs as its table would give it.
double groundedStiffness(const Model& model, int node) {
  double k = 0;
  for (const auto& e : model.elements()) {
    const auto dofs = e->dofs();
    if (dofs.empty() || dofs[0].node != node) continue;
    if (const auto* b = dynamic_cast<const Bearing*>(e.get())) k += b->coefficientsAt(0).kyy;
    if (const auto* p = dynamic_cast<const TiltingPadFilm*>(e.get()))
      k += p->synchronousAt(0).kyy;  // a pad's share, its tilt condensed as the table's
    if (dynamic_cast<const Spring*>(e.get()) && dofs.size() == 1 && dofs[0].dof == Dof::uy)
      k += e->stiffness()(0, 0);
  }
  return k;
}

/// The body as the deck gives it (problems/scenes/README.md section 2): the centre of mass at
/// x = 0, spring A at -l1 and B at +l2, J = m rho^2.
RigidBodyOutcome givenBody(const DeckTwoDofBody& b) {
  RigidBodyOutcome out;
  out.body.m = b.mass;
  out.body.J = b.mass * b.radiusOfGyration * b.radiusOfGyration;
  out.points = {"A", "B"};
  out.x = {-b.l1, b.l2};
  out.stiffness = {b.C1, b.C2};
  out.rigid = FormeShaftRigid{b.mass, out.body.J, b.C1, b.C2, b.l1, b.l2};
  out.modes = formeShaftModes(out.rigid);
  return out;
}

// One runner per rotor kind, each giving its kind's result. All take the deck, the analysis
// and the model alike, so the dispatch below reads as a table.

RotorModesResult runRotorModes(const Deck& deck, const RotorFamily& s, const Model& model) {
  return solveRotorModes(model, s.rotor.speed, optionsOf(deck, s));
}

CampbellOutcome runCampbell(const Deck& deck, const RotorFamily& s, const Model& model) {
  const DeckRotorAnalysis& r = s.rotor;
  CampbellOutcome out;
  out.campbell = solveCampbell(model, r.speeds, optionsOf(deck, s));
  out.order = r.order;
  out.criticalSpeeds = refinedCriticalSpeeds(model, out.campbell, optionsOf(deck, s), r.order);
  out.furtherOrders = r.furtherOrders;
  for (double order : r.furtherOrders)
    for (const CriticalSpeed& c : refinedCriticalSpeeds(model, out.campbell, optionsOf(deck, s), order))
      out.furtherCriticalSpeeds.push_back(c);
  out.onset = instabilityOnset(model, out.campbell, optionsOf(deck, s));
  out.journals = journalCurves(deck);
  out.operating = deckOperatingRange(deck);
  return out;
}

/// The analysis's unbalances on the model's nodes.
std::vector<Unbalance> unbalanceOf(const DeckRotorAnalysis& r, const Model& model) {
  std::vector<Unbalance> unbalance;
  for (const DeckUnbalance& u : r.unbalance)
    unbalance.push_back({model.node(u.point), u.me, u.phase, u.moment});
  return unbalance;
}

UnbalanceOutcome runUnbalance(const Deck& deck, const RotorFamily& s, const Model& model) {
  const DeckRotorAnalysis& r = s.rotor;
  const std::vector<Unbalance> unbalance = unbalanceOf(r, model);
  std::vector<int> nodes;
  for (const std::string& p : r.response) nodes.push_back(model.node(p));
  UnbalanceOutcome out;
  out.responsePoints = r.response;
  // The housings of bearings on pedestals answer after the response points, as
  // "<bearing>_pedestal" (ModelBuilder adds them in the deck's order).
  std::vector<std::string> pedestalBearings;
  for (const DeckBearing& b : deck.rotor.bearings)
    if (b.pedestal) pedestalBearings.push_back(b.name);
  std::size_t housings = 0;
  for (const auto& e : model.elements())
    if (const auto* p = dynamic_cast<const BearingOnPedestal*>(e.get())) {
      nodes.push_back(p->housing());
      out.responsePoints.push_back(pedestalBearings.at(housings++) + "_pedestal");
    }
  out.operating = r.operating;
  const auto response = [&] {
    out.unbalance = solveUnbalance(model, unbalance, r.speeds, nodes, deck.rotor.damping);
  };
  if (!r.operating) {  // no API 684 reading without an operating range
    response();
    return out;
  }
  // The response and the stability half of the verdict are independent: with two cores they
  // run side by side (each the same to the bit; a failure of the response is thrown first).
  const auto stability = [&] {
    out.stability = operatingStability(model, optionsOf(deck, s), *r.operating,
                                       r.speeds.front(), r.minLogDecrement);
  };
  const int parts = std::min(usableCores(), 2);
  runParts(parts, [&](int part) {
    if (part == 0) response();
    if (part == 1 || parts == 1) stability();
  });
  for (std::size_t k = 0; k < out.unbalance.orbits.size(); ++k) {
    // API 684 reads the shaft's response points; a housing's peaks are not part of it.
    if (k >= r.response.size()) {
      out.peaks.emplace_back();
      continue;
    }
    const auto& orbits = out.unbalance.orbits[k];
    std::vector<double> amplitudes;
    for (const Orbit& o : orbits) amplitudes.push_back(o.major());
    out.peaks.push_back(
        unbalancePeaks(model, deck.rotor.damping, out.unbalance.speeds, amplitudes, *r.operating));
  }
  return out;
}

CriticalSpeedMapOutcome runCriticalSpeedMap(const Deck& deck, const RotorFamily& s,
                                            const Model& model) {
  const DeckRotorAnalysis& r = s.rotor;
  CriticalSpeedMapOutcome out;
  Stopwatch clock;
  const auto condensed = padsCondensedModel(deck);
  out.map = solveCriticalSpeedMap(condensed ? *condensed : model, r.stiffnesses, r.criticalSpeeds);
  out.time = clock.lap();
  out.bearings = bearingStiffnessCurves(deck);
  for (BearingStiffnessCurve& b : out.bearings) {
    b.kxxCrossings = mapCrossings(out.map, b.speeds, b.kxx);
    b.kyyCrossings = mapCrossings(out.map, b.speeds, b.kyy);
  }
  return out;
}

/// The model a nonlinear run-up steps: the deck's, except that every tilting-pad bearing keeps
/// each pad's tilt as a dof (massless with `pad_tilts: condensed`, its inertia otherwise), the
/// pads' films acting on them (elements/TiltingPadJournalFilm.hpp); null when the deck's model
/// already is that one (no tilting pads).
std::shared_ptr<const Model> padTiltsModel(const Deck& deck) {
  return modelWithBearings(
      deck, [](const DeckBearing& b) { return b.tiltingPads.has_value(); },
      [](DeckBearing& b) {
        b.padInertia = b.padInertia.value_or(0.0);
        b.everyPadTilt = true;
      });
}

/// The deck's journal bearings as films (run-up `bearings: nonlinear`), each by the theory its
/// coefficients come from (`model: short` or `finite`, or the tilting pads' films, on the same
/// grid): each replaces its model element's coefficients (a tilting-pad bearing's pad films,
/// each pad's tilt a dof of the film's: `model` is padTiltsModel's), its load along the
/// bearing's -x_b.
std::vector<NonlinearJournal> nonlinearJournals(const Deck& deck, const Model& model) {
  std::vector<NonlinearJournal> out;
  for (const DeckBearing& b : deck.rotor.bearings) {
    if (!b.journal) continue;
    NonlinearJournal j;
    j.name = b.name;
    j.node = model.node(b.point);
    if (b.tiltingPads) {
      j.film = std::make_shared<TiltingPadJournalFilm>(*b.journal, *b.tiltingPads, b.journalGrid,
                                                       b.loadAngle);
      // The pads' elements on this journal, in the film's pad order.
      j.ownElements.assign(std::size_t(b.tiltingPads->count), -1);
      j.ownDofs.resize(std::size_t(b.tiltingPads->count));
      for (int e = 0; e < int(model.elements().size()); ++e)
        if (const auto* p = dynamic_cast<const TiltingPadFilm*>(model.elements()[e].get());
            p && p->journal() == j.node && p->pad() >= 0 && p->pad() < b.tiltingPads->count) {
          j.ownElements[std::size_t(p->pad())] = e;
          j.ownDofs[std::size_t(p->pad())] = {p->padNode(), Dof::rx};
        }
    } else {
      for (const auto& [name, element] : model.namedElements())
        if (name == b.name) j.element = element;
      if (b.journalModel == DeckBearing::JournalModel::finite)
        j.film = std::make_shared<FiniteJournalFilm>(*b.journal, b.journalGrid);
      else
        j.film = std::make_shared<ShortJournalFilm>(*b.journal);
    }
    j.load = -b.journal->load * Eigen::Vector2d(std::cos(b.loadAngle), std::sin(b.loadAngle));
    out.push_back(std::move(j));
  }
  return out;
}

/// The polar inertia (kg m^2) of the model's spinning parts about the shaft's axis: each
/// mass's Jp and each shaft element's rho Ip L.
double rotorPolarInertia(const Model& model) {
  double J = 0;
  for (const auto& e : model.elements()) {
    if (const auto* p = dynamic_cast<const PointInertia*>(e.get())) J += p->Jp();
    if (const LineElement* line = asLine(e)) {
      const Section& section = line->section();
      J += section.material.rho * section.Ip() * line->length();
    }
  }
  return J;
}

/// The run-up's torque drive (`speed:`): its torque, the rotor's polar inertia plus the extra.
SpeedDrive speedDriveOf(const DeckRunUp& d, const Model& model) {
  const DeckDrive& deck = *d.drive;
  SpeedDrive drive;
  switch (deck.kind) {
    case DeckDrive::Kind::constant:
      drive.torque = DriveTorque::constant(deck.torques.front());
      break;
    case DeckDrive::Kind::time:
      drive.torque = DriveTorque::againstTime(deck.x, deck.torques);
      break;
    case DeckDrive::Kind::speed:
      drive.torque = DriveTorque::againstSpeed(deck.x, deck.torques);
      break;
  }
  drive.inertia = rotorPolarInertia(model) + deck.extraInertia;
  drive.startSpeed = d.speeds.front();
  drive.duration = d.times.back();
  return drive;
}

RunUpOutcome runRunUp(const Deck& deck, const RotorFamily& s, const Model& deckModel) {
  const DeckRotorAnalysis& r = s.rotor;
  const DeckRunUp& d = r.runUp;
  // Nonlinear tilting pads step their tilts: the model with each pad a dof (the same nodes
  // first, the pads' appended).
  const std::shared_ptr<const Model> tilts =
      d.nonlinearBearings ? padTiltsModel(deck) : nullptr;
  const Model& model = tilts ? *tilts : deckModel;
  RunUpOptions o;
  o.timeStep = d.dt;
  o.hhtAlpha = d.alpha;
  o.start = d.steadyStart ? RunUpStart::steady : RunUpStart::rest;
  o.unbalance = unbalanceOf(r, model);
  o.gravity = Eigen::Vector3d(d.gravity[0], d.gravity[1], d.gravity[2]);
  o.damping = deck.rotor.damping;
  RunUpOutcome out;
  // The rub stations' orbits are reported with the response points' (drawn in their clearance).
  out.responsePoints = r.response;
  for (const DeckRub& rub : d.rubs) {
    auto& points = out.responsePoints;
    if (std::find(points.begin(), points.end(), rub.point) == points.end())
      points.push_back(rub.point);
    out.rubPoints.push_back(rub.point);
    o.rubs.push_back({rub.name, model.node(rub.point), rub.clearance, rub.stiffness, rub.damping,
                      rub.friction, rub.radius, rub.slipVelocity});
  }
  for (const std::string& p : out.responsePoints) o.nodes.push_back(model.node(p));
  o.sampleEvery = d.sampleEvery;
  if (d.nonlinearBearings) o.journals = nonlinearJournals(deck, model);
  if (d.drive) {
    const SpeedDrive drive = speedDriveOf(d, model);
    if (!(drive.inertia > 0))
      throw std::invalid_argument(
          "speed: the rotor has no polar inertia to drive (no mass has Jp and no shaft has "
          "density): give speed: {inertia: ...} (kg*m^2)");
    out.runUp = solveRunUp(model, drive, o);
    out.inertia = drive.inertia;
  } else {
    out.runUp = solveRunUp(model, SpeedProfile::table(d.times, d.speeds), o);
  }
  out.steadyStart = d.steadyStart;
  out.alpha = d.alpha;
  return out;
}

BearingLoadsOutcome runBearingLoads(const Deck& deck, const RotorFamily& s, const Model& model) {
  const DeckRotorAnalysis& r = s.rotor;
  BearingLoadsOutcome out;
  Stopwatch clock;
  const auto& g = r.gravity;
  // Elastic bearings at speed take the synchronous table, as with the pads condensed.
  const auto condensed = padsCondensedModel(deck);
  out.loads =
      solveGravityLoads(condensed ? *condensed : model, Eigen::Vector3d(g[0], g[1], g[2]),
                        r.rigidBearings ? BearingSupport::rigid : BearingSupport::elastic, r.speed);
  out.time = clock.lap();
  for (const DeckBearing& b : deck.rotor.bearings) out.bearingNames.push_back(b.name);
  out.rigidBearings = r.rigidBearings;
  return out;
}

/// The node nearest the middle of the deck's outermost bearings (of the whole shaft with
/// fewer than two bearings): API 684's default station of the added cross-coupling.
int midSpanNode(const Deck& deck, const Model& model) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const DeckBearing& b : deck.rotor.bearings) {
    const double x = model.nodes()[model.node(b.point)].x();
    lo = std::min(lo, x);
    hi = std::max(hi, x);
  }
  if (!(hi > lo))
    for (const Eigen::Vector3d& p : model.nodes()) {
      lo = std::min(lo, p.x());
      hi = std::max(hi, p.x());
    }
  const double middle = (lo + hi) / 2;
  int best = 0;
  for (int n = 1; n < model.nodeCount(); ++n)
    if (std::abs(model.nodes()[n].x() - middle) < std::abs(model.nodes()[best].x() - middle))
      best = n;
  return best;
}

LevelOneOutcome runLevelOne(const Deck& deck, const RotorFamily& s, const Model& model) {
  const DeckRotorAnalysis& r = s.rotor;
  LevelOneOutcome out;
  Stopwatch clock;
  const int node = r.station.empty() ? midSpanNode(deck, model) : model.node(r.station);
  out.station = r.station.empty() ? model.nameOf(node) : r.station;
  if (out.station.empty()) out.station = "node " + std::to_string(node);
  out.stages = int(r.stages.size());
  const double qa = anticipatedCrossCoupling(r.stages, r.speed);
  // The critical speed ratio pins the bearings: the pads do not enter it. Q0 is the full
  // model's (the pads' tilts as dofs where the deck keeps them).
  const auto condensed = padsCondensedModel(deck);
  const CriticalSpeedRatioPoint map = criticalSpeedRatioPoint(
      r.maximumContinuousSpeed, rigidSupportCriticalSpeed(condensed ? *condensed : model, r.speed),
      r.averageGasDensity.value_or(averageGasDensity(r.stages)));
  out.screening = levelOneStability(model, optionsOf(deck, s), node, r.speed, qa, map);
  out.time = clock.lap();
  return out;
}

FrequencyResponseOutcome runFrequencyResponse(const Deck& deck, const RotorFamily& s,
                                              const Model& model) {
  const DeckRotorAnalysis& r = s.rotor;
  const NodeDof in{model.node(r.inputPoint), r.inputDof};
  const NodeDof to{model.node(r.outputPoint), r.outputDof};
  return {solveFrequencyResponse(model, r.speed, in, to, r.frequencies, deck.rotor.damping),
          r.inputPoint + " " + std::string(dofName(r.inputDof)),
          r.outputPoint + " " + std::string(dofName(r.outputDof))};
}

/// The deck's body (FORMAT.md), or the model's between two of its bearing points.
RigidBodyOutcome runRigidBody(const Deck&, const RotorFamily& s, const Model& model) {
  const DeckRotorAnalysis& r = s.rotor;
  if (r.body) return givenBody(*r.body);
  RigidBodyOutcome out;
  out.body = rigidBodyProperties(model);
  for (int i = 0; i < 2; ++i) {
    const int node = model.node(r.bearingPoints[i]);
    out.points[i] = r.bearingPoints[i];
    out.x[i] = model.nodes()[node].x();
    out.stiffness[i] = groundedStiffness(model, node);
    if (!(out.stiffness[i] > 0))
      throw std::invalid_argument("no grounded spring on uy or bearing at point '" + out.points[i] +
                                  "'");
  }
  // A is the spring on the -x side of the centre of mass (the paper's l1).
  if (out.x[0] > out.x[1]) {
    std::swap(out.points[0], out.points[1]);
    std::swap(out.x[0], out.x[1]);
    std::swap(out.stiffness[0], out.stiffness[1]);
  }
  out.rigid = rigidModel(out.body, out.x[0], out.x[1], out.stiffness[0], out.stiffness[1]);
  out.modes = formeShaftModes(out.rigid);
  return out;
}

/// A row of another family than the rotor's: the runner hands none here. Constrained so that
/// a rotor row without its runner above matches no lambda and does not compile.
template <class Spec>
concept NotRotorRow = !std::is_base_of_v<RotorFamily, Spec>;

}  // namespace

AnalysisResult solveRotorAnalysis(const Deck& deck, const DeckAnalysis& a, const Model& model) {
  const auto run = [&](auto runner, const RotorFamily& s) -> AnalysisResult {
    return runner(deck, s, model);
  };
  return std::visit(
      Overloaded{[&](const RotorSpec& s) { return run(runRotorModes, s); },
                 [&](const CampbellSpec& s) { return run(runCampbell, s); },
                 [&](const UnbalanceSpec& s) { return run(runUnbalance, s); },
                 [&](const RigidBodySpec& s) { return run(runRigidBody, s); },
                 [&](const FrequencyResponseSpec& s) { return run(runFrequencyResponse, s); },
                 [&](const CriticalSpeedMapSpec& s) { return run(runCriticalSpeedMap, s); },
                 [&](const BearingLoadsSpec& s) { return run(runBearingLoads, s); },
                 [&](const LevelOneSpec& s) { return run(runLevelOne, s); },
                 [&](const RunUpSpec& s) { return run(runRunUp, s); },
                 [](const NotRotorRow auto&) -> AnalysisResult {
                   throw std::logic_error("solveRotorAnalysis: not a rotor analysis");
                 }},
      a.kind);
}

std::vector<std::string> rotorWarnings(const AnalysisResult& result) {
  if (const auto* c = std::get_if<CampbellOutcome>(&result))
    return campbellWarnings(c->campbell, c->onset);
  if (const auto* m = std::get_if<RotorModesResult>(&result))
    return whirlWarnings(m->coefficients, {m->speed});
  if (const auto* u = std::get_if<UnbalanceOutcome>(&result); u && u->stability)
    if (auto w = onsetWarning(u->stability->onset)) return {*w};
  return {};
}

}  // namespace beamrotor
