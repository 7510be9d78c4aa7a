// Deck reader, part 4: `report:`, the parameters and derived values a person wants to see next
// to the results (e.g. a closed form's switch point w*), by name.
#include <algorithm>

#include "problems/deck/ReaderContext.hpp"
#include "problems/deck/parse/Suggest.hpp"

namespace beamrotor::reader {

void readReport(Context& c) {
  auto block = c.root.get("report");
  if (!block || block->isNull()) return;
  std::vector<std::string> known;
  TakenNames taken;
  for (const auto* list : {&c.deck.parameters, &c.deck.derived})
    for (const auto& [name, value] : *list) known.push_back(name);
  for (const Field& f : block->itemsOrSingle()) {
    const std::string name = f.text();
    const auto find = [&](const std::vector<std::pair<std::string, double>>& list) {
      return std::find_if(list.begin(), list.end(), [&](const auto& p) { return p.first == name; });
    };
    auto it = find(c.deck.parameters);
    if (it == c.deck.parameters.end()) it = find(c.deck.derived);
    if (it == c.deck.derived.end())
      f.fail("no parameter or derived value named '" + name + "'" + didYouMean(name, known) +
             " (defined: " + joinNames(known) + ")");
    claimName(f, name, taken, "a reported value");
    c.deck.reported.push_back(*it);
  }
}

}  // namespace beamrotor::reader
