#include "problems/run/RunTorsion.hpp"

#include <algorithm>

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

}  // namespace

TorsionOutcome runTorsion(const Deck& deck, const TorsionSpec& spec) {
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
