#include "problems/deck/structure/SectionNeeds.hpp"

#include <algorithm>
#include <string>
#include <variant>

namespace beamrotor {

namespace {

std::string theoryWords(BeamTheory t) {
  switch (t) {
    case BeamTheory::eulerBernoulli:
      return "the Euler-Bernoulli element";
    case BeamTheory::timoshenko:
      return "the Timoshenko element";
    case BeamTheory::timoshenkoLinearFullIntegration:
    case BeamTheory::timoshenkoLinearReducedIntegration:
      return "the linear Timoshenko element";
  }
  return "its element";
}

[[noreturn]] void missing(const Deck& deck, const DeckSectionGaps& gaps, const std::string& key,
                          const std::string& why) {
  DeckPlace at = gaps.place;
  at.field = gaps.path + "." + key;
  throw DeckError(deck.path, at,
                  "missing field '" + key + "' of general section '" + gaps.name + "': " + why);
}

}  // namespace

void requireSectionValues(const Deck& deck) {
  if (deck.sectionGaps.empty()) return;
  const bool stresses =
      std::any_of(deck.analyses.begin(), deck.analyses.end(),
                  [](const DeckAnalysis& a) { return a.as<StaticSpec>() != nullptr; });
  const bool bendsAboutY = deck.dofs.contains(Dof::uz);
  const bool torsion = deck.dofs.contains(Dof::rx);
  const bool torsionAnalysis =
      std::any_of(deck.analyses.begin(), deck.analyses.end(),
                  [](const DeckAnalysis& a) { return a.as<TorsionSpec>() != nullptr; });
  for (const DeckSegment& segment : deck.segments) {
    const auto gaps =
        std::find_if(deck.sectionGaps.begin(), deck.sectionGaps.end(),
                     [&](const DeckSectionGaps& g) { return g.name == segment.section->name; });
    if (gaps == deck.sectionGaps.end()) continue;
    if (stresses && gaps->depth)
      missing(deck, *gaps, "depth",
              "the static analysis recovers normal stresses, which need the outer fibre's "
              "distance along y (depth/2 from the axis)");
    if (stresses && bendsAboutY && gaps->width)
      missing(deck, *gaps, "width",
              "in a " + deck.dimension +
                  " model the static analysis recovers normal stresses from bending about y "
                  "too, which need the section's extent along z");
    if (torsion && gaps->J)
      missing(deck, *gaps, "J", "a 3d model twists its beams, which needs the torsion constant");
    if (torsionAnalysis && gaps->J)
      missing(deck, *gaps, "J",
              "the torsion analysis twists the shafts, which needs the torsion constant");
    if (segment.options.theory != BeamTheory::eulerBernoulli && gaps->kappa)
      missing(deck, *gaps, "kappa",
              theoryWords(segment.options.theory) +
                  " needs the shear coefficient (kappa, or kappa_y and kappa_z)");
  }
}

}  // namespace beamrotor
