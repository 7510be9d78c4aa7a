#include "problems/run/RunTorsion.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "fem/assembly/Assembly.hpp"
#include "fem/modal/HarmonicResponse.hpp"
#include "fem/modal/Modal.hpp"
#include "problems/run/ModelBuilder.hpp"

namespace beamrotor {

namespace {

template <class Item, class Keep>
void keepOnly(std::vector<Item>& items, Keep keep) {
  items.erase(std::remove_if(items.begin(), items.end(), [&](Item& i) { return !keep(i); }),
              items.end());
}

/// The deck as a train in twist: rx alone, with what acts on it.
Deck torsionDeck(const Deck& deck) {
  Deck train = deck;
  train.dofs = DofSet::torsion();
  for (DeckSupport& s : train.supports)
    keepOnly(s.dofs, [](const std::pair<Dof, double>& d) { return d.first == Dof::rx; });
  keepOnly(train.supports, [](const DeckSupport& s) { return !s.dofs.empty(); });
  keepOnly(train.springs, [](const DeckSpring& s) { return s.dof == Dof::rx; });
  for (DeckHinge& h : train.hinges) keepOnly(h.released, [](Dof d) { return d == Dof::rx; });
  keepOnly(train.hinges, [](const DeckHinge& h) { return !h.released.empty(); });
  // Vibration about equilibrium: no loads; bearings and stops act on the other dofs.
  train.loads.clear();
  train.loadCases.clear();
  train.combinations.clear();
  train.contacts.clear();
  train.rotor.bearings.clear();
  return train;
}

bool heldInTwist(const Deck& train) {
  return !train.supports.empty() ||
         std::any_of(train.springs.begin(), train.springs.end(),
                     [](const DeckSpring& s) { return s.toPoint.empty(); });
}

/// A shift below zero on the scale of the train's first elastic eigenvalue, for a train that
/// turns freely: the shaft's end-to-end stiffness over the whole polar inertia, k / J, lies
/// within a small factor of it (two equal disks on a shaft: k / 2J against 2k / J), so
/// K - shift M stays well conditioned and the rotation (omega^2 = 0) and the first elastic
/// mode stay apart in the shift-inverted spectrum.
double freeTrainShift(const Deck& train) {
  double flexibility = 0, inertia = 0;
  for (const DeckSegment& s : train.segments) {
    flexibility += s.length / s.section->GJ();
    inertia += s.section->material.rho * s.section->Ip() * s.length;
  }
  for (const DeckMass& m : train.masses) inertia += m.Jp;
  return -1 / (flexibility * inertia);
}

/// The train's analogue of freeTrainShift: every shaft's, coupling's and mesh's flexibility
/// in series over the whole polar inertia (ratios aside: a scale, not a value).
double freeTrainShift(const TrainSpec& train) {
  double flexibility = 0, inertia = 0;
  for (const TrainShaft& shaft : train.shafts)
    for (const Segment& s : shaft.segments) {
      flexibility += s.length / s.section->GJ();
      inertia += s.section->material.rho * s.section->Ip() * s.length;
    }
  for (const TrainJoint& j : train.couplings) flexibility += 1 / j.stiffness;
  for (const TrainJoint& j : train.gears) flexibility += 1 / j.stiffness;
  for (const TrainDisk& d : train.disks) inertia += d.Jp;
  return -1 / (flexibility * inertia);
}

int shaftOf(const TrainSpec& train, const std::string& name) {
  for (std::size_t i = 0; i < train.shafts.size(); ++i)
    if (train.shafts[i].name == name) return int(i);
  throw std::logic_error("no shaft " + name);
}

/// The complex torque an element carries at w under the complex twist u: (K + i w C) u_e,
/// its first entry for a gear mesh (on the pinion's side), its last otherwise (the twist of
/// its second node over its first times the stiffness).
std::complex<double> trainElementTorque(const Element& e, const DofMap& dofs, const ComplexVector& u,
                                   double w, bool gear) {
  const ElementVector re = gather(e, dofs, u.real()), im = gather(e, dofs, u.imag());
  const ElementMatrix K = e.stiffness(), C = e.damping();
  const Eigen::Index i = gear ? 0 : re.size() - 1;
  std::complex<double> t(K.row(i).dot(re), K.row(i).dot(im));
  if (C.size() > 0) t += std::complex<double>(0, w) * std::complex<double>(C.row(i).dot(re), C.row(i).dot(im));
  return t;
}

/// The harmonic torques grouped by frequency: each distinct order of the reference shaft's
/// speed and the load vector of the torques at that order. Independent of the speed.
struct TrainExcitation {
  std::vector<double> orders;
  std::vector<ComplexVector> loads;
};

TrainExcitation trainExcitation(const TrainSpec& train, const TorsionSpec& spec, const Model& model,
                                const DofMap& dofs, const std::vector<double>& ratios) {
  TrainExcitation out;
  for (const HarmonicTorque& h : spec.torques) {
    const double order = h.order * ratios[shaftOf(train, h.at.shaft)];
    auto same = std::find_if(out.orders.begin(), out.orders.end(),
                             [&](double o) { return std::abs(o - order) <= 1e-12 * order; });
    if (same == out.orders.end()) {
      out.orders.push_back(order);
      out.loads.push_back(ComplexVector::Zero(dofs.size()));
      same = out.orders.end() - 1;
    }
    const int eq = dofs.equation(model.node(h.at.name()), Dof::rx);
    out.loads[same - out.orders.begin()](eq) += std::polar(h.amplitude, h.phase);
  }
  return out;
}

/// The train's steady response at the reference speed `speed` (rad/s); `peakOf` samples the
/// excitation's orders.
TorsionResponse trainResponse(const TrainSpec& train, const TrainMesh& mesh,
                              const HarmonicResponse& harmonic, const TrainExcitation& excitation,
                              const HarmonicPeak& peakOf, double speed) {
  const Model& model = harmonic.model();
  const DofMap& dofs = harmonic.dofs();
  TorsionResponse out;
  out.speed = speed;
  out.orders = excitation.orders;
  std::vector<ComplexVector> twist;
  for (std::size_t j = 0; j < out.orders.size(); ++j)
    twist.push_back(harmonic.solve(out.orders[j] * speed, excitation.loads[j]));
  const auto trace = [&](const std::string& name, auto&& amplitudeOf) {
    ResponseTrace r{name, {}, 0};
    for (std::size_t j = 0; j < out.orders.size(); ++j)
      r.amplitudes.push_back(amplitudeOf(twist[j], out.orders[j] * speed));
    r.peak = peakOf(r.amplitudes);
    return r;
  };
  const auto jointTrace = [&](const TrainJoint& j, int element, bool gear) {
    return trace(j.name, [&](const ComplexVector& u, double w) {
      return trainElementTorque(*model.elements()[element], dofs, u, w, gear);
    });
  };
  for (std::size_t i = 0; i < train.couplings.size(); ++i)
    out.torques.push_back(jointTrace(train.couplings[i], mesh.couplings[i], false));
  for (std::size_t i = 0; i < train.gears.size(); ++i)
    out.torques.push_back(jointTrace(train.gears[i], mesh.gears[i], true));
  for (std::size_t s = 0; s < train.shafts.size(); ++s) {
    ResponseTrace largest{train.shafts[s].name, {}, -1};
    for (const Beam* beam : mesh.shafts[s].beams) {
      ResponseTrace r = trace(train.shafts[s].name, [&](const ComplexVector& u, double w) {
        return trainElementTorque(*beam, dofs, u, w, false);
      });
      if (r.peak > largest.peak) largest = std::move(r);
    }
    out.torques.push_back(std::move(largest));
  }
  for (const TrainShaft& shaft : train.shafts) {
    std::vector<std::string> stations{"start", "end"};
    for (const NamedPoint& p : shaft.stations) stations.push_back(p.name);
    for (const std::string& station : stations) {
      const int eq = dofs.equation(model.node(shaft.name + "." + station), Dof::rx);
      out.twists.push_back(trace(shaft.name + "." + station,
                                 [&](const ComplexVector& u, double) { return u(eq); }));
    }
  }
  return out;
}

TorsionOutcome runTrain(const Deck& deck, const TorsionSpec& spec) {
  const TrainSpec& train = deck.train;
  TorsionOutcome out;
  auto model = std::make_shared<Model>();
  const TrainMesh mesh = buildTrain(*model, train);
  out.model = model;
  out.free = true;  // a train has no support in twist
  ModalOptions options;
  options.modes = spec.modes;
  options.shift = spec.shiftGiven ? spec.shift : freeTrainShift(train);
  out.modes = solveModes(*model, options);
  // Speeds over the reference shaft's.
  const std::vector<double> toFirst = shaftSpeedRatios(train);
  for (std::size_t i = 0; i < train.shafts.size(); ++i) {
    out.shafts.push_back(train.shafts[i].name);
    out.speedRatios.push_back(toFirst[i] / toFirst[spec.reference]);
  }
  out.reference = train.shafts[spec.reference].name;
  out.orders = spec.orders;
  if (spec.speeds) {
    out.speedFrom = spec.speeds->from;
    out.speedTo = spec.speeds->to;
    for (double order : spec.orders)
      for (std::size_t m = 0; m < out.modes.modes.size(); ++m) {
        const double f = out.modes.modes[m].frequencyHz;
        const double speed = 2 * std::numbers::pi * f / order;
        if (!out.modes.modes[m].rigidBody && speed >= out.speedFrom && speed <= out.speedTo)
          out.crossings.push_back({order, int(m) + 1, f, speed});
      }
    std::sort(out.crossings.begin(), out.crossings.end(),
              [](const TorsionCrossing& a, const TorsionCrossing& b) { return a.speed < b.speed; });
  }
  out.excitation = spec.torques;
  if (spec.torques.empty()) return out;
  const HarmonicResponse harmonic(*model);
  const TrainExcitation excitation =
      trainExcitation(train, spec, *model, harmonic.dofs(), out.speedRatios);
  const HarmonicPeak peakOf(excitation.orders);
  const auto responseAt = [&](double speed) {
    return trainResponse(train, mesh, harmonic, excitation, peakOf, speed);
  };
  if (spec.speed > 0) out.atSpeed = responseAt(spec.speed);
  if (spec.speeds)
    for (int i = 0; i <= spec.speeds->steps; ++i) {
      const double speed =
          spec.speeds->from + (spec.speeds->to - spec.speeds->from) * i / spec.speeds->steps;
      if (speed > 0) out.sweep.push_back(responseAt(speed));
    }
  return out;
}

}  // namespace

TorsionOutcome runTorsion(const Deck& deck, const TorsionSpec& spec) {
  if (!deck.train.shafts.empty()) return runTrain(deck, spec);
  const Deck train = torsionDeck(deck);
  TorsionOutcome out;
  out.free = !heldInTwist(train);
  out.model = buildModel(train);
  ModalOptions options;
  options.modes = spec.modes;
  options.shift = spec.shiftGiven ? spec.shift : out.free ? freeTrainShift(train) : 0;
  out.modes = solveModes(*out.model, options);
  return out;
}

}  // namespace beamrotor
