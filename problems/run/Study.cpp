#include "problems/run/Study.hpp"

#include "fem/solvers/AvailableMemory.hpp"
#include "problems/deck/DeckReader.hpp"
#include "problems/deck/structure/FormulationOption.hpp"
#include "problems/deck/study/SweepOption.hpp"
#include "problems/run/MemoryEstimate.hpp"

namespace beamrotor {

namespace {

Study solve(const DeckSource& source, const StudyRequest& request, const SweepProgress& progress) {
  std::vector<ParameterOverride> overrides;
  for (const std::string& s : request.sets) overrides.push_back(parseOverride(s, source.path));
  const DeckAdjustment adjust = [&](Deck& deck) {
    if (!request.formulation.empty()) applyFormulationOption(request.formulation, deck);
  };
  if (request.noSweep && !request.sweep.empty())
    throw DeckError(source.path, DeckPlace{0, 0, "--no-sweep"},
                    "contradicts --sweep " + request.sweep + "; give one of the two");
  Study study{readDeck(source, overrides), std::nullopt, std::nullopt};
  adjust(study.deck);
  if (!request.sweep.empty()) {
    study.deck.sweep = parseSweepOption(request.sweep, study.deck);
    if (findOverride(overrides, study.deck.sweep->parameter))
      throw DeckError(source.path, study.deck.sweep->place,
                      "'" + study.deck.sweep->parameter + "' is both set (--set) and swept");
  }
  if (request.noSweep) study.deck.sweep.reset();
  requireMemory(study.deck, study.deck.sweep ? study.deck.sweep->values.size() : 1,
                availableMemoryBytes());
  if (study.deck.sweep)
    study.sweep = runSweep(source, overrides, study.deck, progress, adjust);
  else
    study.run = runDeck(study.deck);
  std::vector<std::string> set;
  for (const ParameterOverride& o : overrides) set.push_back(o.name);
  if (study.run) study.run->setParameters = set;
  if (study.sweep)
    for (RunResult& run : study.sweep->runs) run.setParameters = set;
  return study;
}

}  // namespace

Study solveStudy(const StudyRequest& request, const SweepProgress& progress) {
  return solve(loadDeckFile(request.deckPath), request, progress);
}

Study solveStudyText(const std::string& text, const StudyRequest& request) {
  return solve(parseDeckText(text, request.deckPath), request, {});
}

}  // namespace beamrotor
