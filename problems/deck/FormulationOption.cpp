#include "problems/deck/FormulationOption.hpp"

#include "problems/deck/SectionNeeds.hpp"
#include "problems/deck/Suggest.hpp"

namespace beamrotor {

void applyFormulationOption(const std::string& theory, Deck& deck) {
  static const std::vector<std::string> kChoices{"euler-bernoulli", "timoshenko"};
  if (theory != kChoices[0] && theory != kChoices[1])
    throw DeckError(deck.path, DeckPlace{0, 0, "--formulation " + theory},
                    "expected " + joinNames(kChoices) + didYouMean(theory, kChoices));
  const BeamTheory chosen =
      theory == kChoices[1] ? BeamTheory::timoshenko : BeamTheory::eulerBernoulli;
  deck.beam.theory = chosen;
  for (DeckSegment& s : deck.segments) s.options.theory = chosen;
  requireSectionValues(deck);  // a Timoshenko beam needs every section's shear coefficient
}

}  // namespace beamrotor
