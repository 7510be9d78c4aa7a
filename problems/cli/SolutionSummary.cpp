// The summary's lines on one static solution (see SolutionSummary.hpp).
#include "problems/cli/SolutionSummary.hpp"

#include <algorithm>

#include "problems/cli/Summary.hpp"
#include "problems/output/structure/Reactions.hpp"

namespace beamrotor::cli {

const char* motionUnit(Dof d) {
  return isRotation(d) ? "rad" : "m";
}

std::vector<const DeckPoint*> reportedPoints(const Deck& deck) {
  std::vector<const DeckPoint*> out;
  for (const DeckPoint& p : deck.points)
    if (p.name != "start" && p.name != "end") out.push_back(&p);
  if (out.empty())
    for (const DeckPoint& p : deck.points) out.push_back(&p);
  return out;
}

void printReactions(std::ostream& out, const StaticResult& r, const std::string& indent) {
  const std::vector<SupportReactions> supports = reactionsBySupport(r);
  out << indent << "reactions (force on the structure; N, N m)";
  if (supports.size() > kSummarySupports)
    out << ", the first " << kSummarySupports << " of " << supports.size()
        << " supports (all in results.json)";
  out << ":\n";
  // Named as in results.json and sweep.csv: fx ... mz.
  for (std::size_t i = 0; i < supports.size() && i < kSummarySupports; ++i) {
    out << indent << "  " << padded(supports[i].support, 12);
    for (const auto& [dof, value] : supports[i].components)
      out << padded(std::string(reactionName(dof)) + " " + formatValue(value) + " " +
                        std::string(reactionUnit(dof)),
                    22);
    out << "\n";
  }
}

void printPointDisplacements(std::ostream& out, const Deck& deck, const RunResult& run,
                             const StaticResult& r, const std::string& indent) {
  const std::vector<const DeckPoint*> points = reportedPoints(deck);
  out << indent << "displacements at points (m, rad):\n";
  for (const DeckPoint* p : points) {
    const int node = run.model->node(p->name);
    out << indent << "  " << padded(p->name, 12);
    if (deck.frame) {
      // A frame's points are places in space, not stations along one line.
      const Eigen::Vector3d& x = run.model->nodes()[node];
      std::string at = "at (" + formatValue(x.x()) + ", " + formatValue(x.y());
      if (deck.dimension == "3d") at += ", " + formatValue(x.z());
      out << padded(at + ") m", 24);
    } else {
      out << padded("x = " + formatValue(p->at) + " m", 16);
    }
    const auto hinge = std::find_if(r.hinges.begin(), r.hinges.end(),
                                    [&](const SideRotations& h) { return h.node == node; });
    for (Dof d : kAllDofs) {
      if (!deck.dofs.contains(d)) continue;
      const std::string name(dofName(d));
      if (!isRotation(d) || hinge == r.hinges.end()) {
        out << padded(
            name + " " + formatValue(r.displacement(node, dofIndex(d))) + " " + motionUnit(d), 22);
        continue;
      }
      // A hinge: the beam end on each side turns on its own.
      for (const auto& [side, value] :
           {std::pair{" left ", &hinge->left}, std::pair{" right ", &hinge->right}})
        if (*value)
          out << padded(name + side + formatValue((**value)[dofIndex(d) - 3]) + " rad", 26);
    }
    out << "\n";
  }
}

}  // namespace beamrotor::cli
