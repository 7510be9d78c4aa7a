#include "problems/verify/DeckChecks.hpp"

#include <algorithm>

#include "fem/timing/Stopwatch.hpp"
#include "problems/deck/parse/Field.hpp"
#include "problems/run/Study.hpp"

namespace beamrotor::verify {

namespace {

/// The checks of `run` that did not apply, each with its deck's condition.
void collectNotApplied(const Deck& deck, const RunResult& run, const std::string& label,
                       std::vector<NotApplied>& out) {
  for (const std::string& name : run.skippedChecks) {
    std::string why = "its when: condition is false here";
    for (const DeckCheck& k : deck.checks)
      if (k.name == name) why = "when: " + k.condition + " is false here";
    out.push_back({label, name, why});
  }
}

DeckChecks checkDeck(const std::filesystem::path& path) {
  DeckChecks out;
  out.deck = path.filename().string();
  Stopwatch clock;
  try {
    StudyRequest request;
    request.deckPath = path.string();
    const Study s = solveStudy(request);
    out.title = s.deck.title;
    if (s.run) {
      for (const Check& c : s.run->checks) out.checks.push_back({"", c});
      collectNotApplied(s.deck, *s.run, "", out.notApplied);
    } else {
      for (std::size_t i = 0; i < s.sweep->runs.size(); ++i) {
        const std::string label = s.sweep->parameter + " = " + formatNumber(s.sweep->values[i]);
        for (const Check& c : s.sweep->runs[i].checks) out.checks.push_back({label, c});
        collectNotApplied(s.deck, s.sweep->runs[i], label, out.notApplied);
      }
    }
  } catch (const std::exception& e) {  // DeckError, DeckSolveError: one line each
    out.error = e.what();
  }
  out.seconds = clock.lap();
  return out;
}

}  // namespace

std::vector<DeckChecks> runDeckChecks(const std::vector<std::filesystem::path>& decks) {
  std::vector<DeckChecks> out;
  for (const auto& path : decks) out.push_back(checkDeck(path));
  return out;
}

std::vector<std::filesystem::path> decksIn(const std::filesystem::path& dir) {
  std::vector<std::filesystem::path> decks;
  for (const auto& entry : std::filesystem::directory_iterator(dir))
    if (entry.is_regular_file() && entry.path().extension() == ".yaml")
      decks.push_back(entry.path());
  std::sort(decks.begin(), decks.end());
  return decks;
}

}  // namespace beamrotor::verify
