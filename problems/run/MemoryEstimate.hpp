// What a deck's run will need in memory, estimated from the deck alone before anything is
// built: the model and its factorisation, each analysis' working vectors and the results it
// keeps (mode shapes, histories, frames), times the runs a sweep keeps. A run that cannot fit
// is refused with the estimate and the memory available, instead of ending in std::bad_alloc
// or the kernel's out-of-memory killer part-way through.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "problems/deck/Deck.hpp"

namespace beamrotor {

/// One part of the estimate.
struct MemoryPart {
  std::string what;  ///< e.g. "transient 'shake': 1000 frames of 100001 nodes"
  double bytes = 0;
  DeckPlace place;  ///< where the deck asks for it
};

/// The parts of one run of `deck`, largest first.
std::vector<MemoryPart> estimateRunMemory(const Deck& deck);

/// Throws DeckSolveError, at the largest part's place, when `runs` runs of `deck` (a sweep
/// keeps every run's results) need more than `available` bytes; the message gives the total,
/// the largest part and what is available.
void requireMemory(const Deck& deck, std::size_t runs, std::size_t available);

}  // namespace beamrotor
