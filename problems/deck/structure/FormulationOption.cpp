#include "problems/deck/structure/FormulationOption.hpp"

#include "problems/deck/structure/Formulations.hpp"
#include "problems/deck/structure/SectionNeeds.hpp"
#include "problems/deck/parse/Suggest.hpp"

namespace beamrotor {

void applyFormulationOption(const std::string& theory, Deck& deck) {
  const std::optional<BeamTheory> chosen = formulationNamed(theory);
  if (!chosen)
    throw DeckError(deck.path, DeckPlace{0, 0, "--formulation " + theory},
                    "expected " + joinNames(formulationNames()) +
                        didYouMean(theory, formulationNames()));
  deck.beam.theory = *chosen;
  for (DeckSegment& s : deck.segments) s.options.theory = *chosen;
  requireSectionValues(deck);  // a Timoshenko beam needs every section's shear coefficient
}

}  // namespace beamrotor
