#include "problems/cli/AdequateSummary.hpp"

#include <cstdio>

namespace beamrotor::cli {

void printAdequateChoice(std::ostream& out, const AdequateChoice& c) {
  char line[256];
  std::snprintf(line, sizeof line,
                "accuracy %.3g: chose %s, %d elements per segment (%d dofs); estimated error "
                "%.2e (mesh %.2e",
                c.target, c.formulation.c_str(), c.elementsPerSegment, c.dofs, c.estimatedError,
                c.meshError);
  out << line;
  if (c.shearContribution) {
    std::snprintf(line, sizeof line, ", shear contribution %.2e", *c.shearContribution);
    out << line;
  }
  std::snprintf(line, sizeof line,
                ")\n  against the deck's own mesh (%s, %d dofs, %.3g s): %d dofs fewer, "
                "%.3g s instead (search %.3g s)\n",
                c.deckFormulation.c_str(), c.deckDofs, c.deckSeconds, c.deckDofs - c.dofs,
                c.seconds, c.searchSeconds);
  out << line;
  if (c.rigidBodyError) {
    std::snprintf(line, sizeof line,
                  "  rigid body on two springs: its two frequencies differ from the beam "
                  "model's by %.2e: %s\n",
                  *c.rigidBodyError,
                  c.rigidBodyAdequate ? "adequate at this accuracy, no beam model needed"
                                      : "not adequate at this accuracy, keep the beam model");
    out << line;
  }
}

}  // namespace beamrotor::cli
