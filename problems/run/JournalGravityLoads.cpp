#include "problems/run/JournalGravityLoads.hpp"

#include <algorithm>
#include <exception>
#include <stdexcept>
#include <vector>

#include "fem/assembly/ParallelParts.hpp"
#include "fem/rotor/GravityLoads.hpp"
#include "problems/deck/parse/Field.hpp"
#include "problems/deck/rotor/JournalTable.hpp"
#include "problems/run/ModelBuilder.hpp"

namespace beamrotor {

namespace {

constexpr double kStandardGravity = 9.81;  // m/s^2, along -y: the journal's load direction

bool waitsForLoad(const DeckBearing& b) {
  return b.loadFromGravity && b.table.empty();
}

/// Where a bearing's `load: gravity` is written.
DeckPlace loadPlace(const DeckBearing& b) {
  DeckPlace place = b.place;
  place.field += ".load";
  return place;
}

}  // namespace

bool needsJournalLoads(const Deck& deck) {
  for (const DeckBearing& b : deck.rotor.bearings)
    if (waitsForLoad(b)) return true;
  return false;
}

Deck withJournalLoads(const Deck& deck) {
  // 1. The rotor with placeholder bearings (they become pinned supports below).
  //    Pinned, a bearing carries the same load with or without a pedestal in series: the
  //    pedestals are left out, so that every bearing is one the pinning finds.
  Deck placeholder = deck;
  //    So are the pads' tilts (each bearing then one element on its journal).
  for (DeckBearing& b : placeholder.rotor.bearings) {
    b.pedestal.reset();
    b.padInertia.reset();
  }
  for (DeckBearing& b : placeholder.rotor.bearings)
    if (waitsForLoad(b)) {
      b.speeds.clear();
      b.table = {BearingCoefficients::isotropic(1)};
    }
  const auto model = buildModel(placeholder);
  GravityLoads loads;
  try {
    loads = solveGravityLoads(*model, Eigen::Vector3d(0.0, -kStandardGravity, 0.0),
                              BearingSupport::rigid);
  } catch (const std::exception& e) {
    for (const DeckBearing& b : deck.rotor.bearings)
      if (waitsForLoad(b)) throw DeckError(deck.path, b.place, std::string("load: gravity: ") + e.what());
  }
  // 2. Bearings are the model's only Bearing elements, added in deck order.
  Deck out = deck;
  std::vector<std::size_t> waiting;
  for (std::size_t i = 0; i < out.rotor.bearings.size(); ++i) {
    DeckBearing& b = out.rotor.bearings[i];
    if (!waitsForLoad(b)) continue;
    const double W = loads.bearings.at(i).fy;
    if (!(W > 0))
      throw DeckError(deck.path, loadPlace(b),
                      "load: gravity: on pinned bearings the rotor's weight gives bearing '" +
                          b.name + "' " + formatNumber(W) +
                          " N (the shaft lifts off it); give its load as a number");
    b.journal->load = W;
    waiting.push_back(i);
  }
  // 3. Their tables, one bearing per core at a time: each bearing's table is its own work
  //    (the same to the bit on one core or many); the first failure in deck order is thrown.
  const int parts = std::max(1, std::min(usableCores(), int(waiting.size())));
  std::vector<std::exception_ptr> failures(waiting.size());
  runParts(parts, [&](int part) {
    for (std::size_t k = std::size_t(part); k < waiting.size(); k += std::size_t(parts)) {
      DeckBearing& b = out.rotor.bearings[waiting[k]];
      try {
        fillJournalTable(b);
      } catch (const std::invalid_argument& e) {
        failures[k] = std::make_exception_ptr(
            DeckError(deck.path, loadPlace(b),
                      "load: gravity (" + formatNumber(b.journal->load) + " N): " + e.what()));
      } catch (...) {
        failures[k] = std::current_exception();
      }
    }
  });
  for (const std::exception_ptr& failure : failures)
    if (failure) std::rethrow_exception(failure);
  return out;
}

}  // namespace beamrotor
