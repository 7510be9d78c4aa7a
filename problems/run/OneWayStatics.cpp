#include "problems/run/OneWayStatics.hpp"

#include <stdexcept>

#include "problems/deck/parse/DeckError.hpp"
#include "problems/run/ModelBuilder.hpp"

namespace beamrotor {

std::optional<OneWaySolution> solveOneWayMembers(const Deck& deck) {
  if (!deck.frame || !deck.frame->hasOneWayMembers()) return std::nullopt;
  const std::vector<DeckMember>& members = deck.frame->members;
  std::vector<OneWayMember> oneWay;
  std::vector<std::size_t> memberOf;  // each one-way member's index among the frame's
  for (std::size_t m = 0; m < members.size(); ++m)
    if (members[m].acts != MemberAction::both) {
      oneWay.push_back({deck.segments[m].name, members[m].acts});
      memberOf.push_back(m);
    }
  const auto build = [&](const std::vector<bool>& slack) -> std::shared_ptr<const Model> {
    std::vector<bool> slackMembers(members.size(), false);
    for (std::size_t i = 0; i < slack.size(); ++i) slackMembers[memberOf[i]] = slack[i];
    return buildModel(deck, slackMembers);
  };
  try {
    return solveWithOneWayMembers(build, oneWay);
  } catch (const DeckDiagnostic&) {
    throw;
  } catch (const std::exception& e) {
    throw DeckSolveError(deck.path, members[memberOf.front()].place, e.what());
  }
}

}  // namespace beamrotor
