// Memory estimate of a deck's run (see MemoryEstimate.hpp). The per-element figure of statics
// is measured (fem/solvers/HeapReserve.hpp); the rest counts the doubles the analyses keep.
#include "problems/run/MemoryEstimate.hpp"

#include <algorithm>
#include <cmath>
#include <variant>

#include "fem/solvers/AvailableMemory.hpp"
#include "fem/solvers/HeapReserve.hpp"
#include "fem/solvers/SymmetricEigen.hpp"

namespace beamrotor {

namespace {

constexpr double kDouble = sizeof(double);
constexpr double kTableCell = 48;  // one CSV cell as the writers hold it before writing

}  // namespace

std::vector<MemoryPart> estimateRunMemory(const Deck& deck) {
  double elements = 0;
  for (const DeckSegment& s : deck.segments) elements += s.elementEstimate();
  elements += double(deck.points.size());  // each point may cut an element in two
  const double nodes = elements + double(deck.points.size()) + 1;
  const int perNode = deck.dofs.size();
  const double dofs = nodes * perNode;

  std::vector<MemoryPart> parts;
  parts.push_back({"the model and its factorisation (" +
                       std::to_string(static_cast<long long>(nodes)) + " nodes)",
                   double(estimatedStaticBytes(
                       static_cast<long long>(elements + double(deck.masses.size())), perNode)),
                   deck.segments.empty() ? DeckPlace{} : deck.segments.front().place});
  for (const DeckAnalysis& a : deck.analyses) {
    const std::string name = a.type() + " '" + a.name + "'";
    const int modes = modesComputed(a.kind);
    if (const auto* transient = a.as<TransientSpec>()) {
      const DeckTransient& t = transient->run;
      const double steps = std::round(t.end / t.dt);
      const double samples = std::floor(steps / std::max(1, t.sampleEvery)) + 2;
      const double columns = 1 + 4 + 4.0 * double(t.histories.size());  // t, energy, u v a value
      parts.push_back(
          {name + ": " + std::to_string(static_cast<long long>(samples)) + " samples of " +
               std::to_string(t.histories.size()) + " histories",
           samples * (columns * kDouble + (1 + double(t.histories.size())) * kTableCell), a.place});
      if (t.frames > 0)
        parts.push_back({name + ": " + std::to_string(t.frames) + " frames of " +
                             std::to_string(static_cast<long long>(nodes)) + " nodes",
                         double(t.frames + 1) * nodes * kDofKinds * kDouble, a.place});
    } else if (a.as<ModalSpec>() || a.as<RotorSpec>() || a.as<CampbellSpec>()) {
      // Lanczos vectors, the shapes kept and, for rotors, complex numbers.
      const double lanczos = std::min(dofs, double(lanczosBasisSize(modes)));
      const double complex = a.as<ModalSpec>() ? 1 : 2;
      const auto* campbell = a.as<CampbellSpec>();
      const double speeds = campbell ? double(campbell->rotor.speeds.size()) : 1;
      parts.push_back(
          {name + ": " + std::to_string(modes) + " modes",
           complex * kDouble * (lanczos * dofs + speeds * modes * (dofs + nodes * kDofKinds)),
           a.place});
    }
  }
  std::stable_sort(parts.begin(), parts.end(),
                   [](const MemoryPart& a, const MemoryPart& b) { return a.bytes > b.bytes; });
  return parts;
}

void requireMemory(const Deck& deck, std::size_t runs, std::size_t available) {
  const std::vector<MemoryPart> parts = estimateRunMemory(deck);
  double total = 0;
  for (const MemoryPart& p : parts) total += p.bytes;
  total *= double(std::max<std::size_t>(1, runs));
  if (total <= double(available)) return;
  const MemoryPart& largest = parts.front();
  throw DeckSolveError(
      deck.path, largest.place,
      "this run needs about " + memoryText(total) +
          (runs > 1 ? " (" + std::to_string(runs) + " sweep values kept)" : std::string()) +
          " but " + memoryText(double(available)) + " are available; the largest part is " +
          largest.what + " (" + memoryText(largest.bytes) +
          "): use fewer elements, modes, frames, samples or sweep values");
}

}  // namespace beamrotor
