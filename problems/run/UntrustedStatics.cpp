#include "problems/run/UntrustedStatics.hpp"

#include <cstdio>
#include <stdexcept>

#include "fem/model/LineElement.hpp"
#include "problems/deck/parse/Field.hpp"
#include "problems/run/AdequateModel.hpp"

namespace beamrotor {

namespace {

/// Why the `accuracy:` search cannot choose a mesh for `deck`, or "" when it can.
std::string searchUnfit(const Deck& deck) {
  if (deck.segments.empty()) return "it chooses the mesh of a line's segments, and this deck has none";
  if (deck.checks.empty()) return "it needs checks to measure, and this deck has none";
  for (const DeckAnalysis& a : deck.analyses)
    if (!a.as<StaticSpec>() && !a.as<ModalSpec>() && !a.as<RigidBodySpec>())
      return "it applies to static, modal and rigid-body analyses, and '" + a.name +
             "' is a " + a.type() + " analysis";
  return {};
}

/// What the `accuracy:` search finds for `deck`, as the end of a sentence.
std::string cheapestAdequateMesh(const Deck& deck) {
  const std::string ground = searchUnfit(deck);
  if (!ground.empty())
    return "the accuracy: search cannot choose a mesh here (" + ground +
           "); fewer elements give a more accurate solution";
  Deck search = acceptingRoundOff(deck);
  search.accuracy = DeckAccuracy{kRemedyAccuracy, {}};
  try {
    const AdequateChoice chosen = *runAdequateModel(search).adequate;
    return "the accuracy: search (" + formatNumber(kRemedyAccuracy) +
           " on the deck's checks) finds " + std::to_string(chosen.elementsPerSegment) +
           " elements per segment adequate (" + chosen.formulation + ", " +
           std::to_string(chosen.elements) + " elements, estimated error " +
           formatNumber(chosen.estimatedError) + ")";
  } catch (const DeckDiagnostic& e) {
    return "the accuracy: search (" + formatNumber(kRemedyAccuracy) +
           " on the deck's checks) found no adequate mesh: " + e.message();
  }
}

}  // namespace

void refuseUntrustedStatics(const Deck& deck, const Model& model, const StaticResult& r,
                            const std::string& what) {
  if (!(r.roundOff >= kNoTrustedDigit)) return;
  int lineElements = 0;
  for (const auto& e : model.elements()) lineElements += asLine(e) != nullptr;
  char estimate[160];
  std::snprintf(estimate, sizeof estimate,
                "the static solution's round-off error, bounded by measurement at %.2g, leaves "
                "no digit to trust (%d beam elements)",
                r.roundOff, lineElements);
  std::string message = estimate;
  if (!what.empty()) message = what + ": " + message;
  throw std::runtime_error(message + "; " + cheapestAdequateMesh(deck) +
                           ". To keep such a result anyway, state accept_round_off: true on "
                           "this static analysis");
}

Deck acceptingRoundOff(Deck deck) {
  for (DeckAnalysis& a : deck.analyses)
    if (auto* s = std::get_if<StaticSpec>(&a.kind)) s->acceptRoundOff = true;
  return deck;
}

}  // namespace beamrotor
