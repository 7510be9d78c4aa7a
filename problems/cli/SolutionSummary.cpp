// The summary's lines on one static solution (see SolutionSummary.hpp).
#include "problems/cli/SolutionSummary.hpp"

#include <algorithm>
#include <map>

#include "problems/cli/Summary.hpp"
#include "problems/output/structure/MemberEndRotations.hpp"
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

namespace {

/// Forces by name under `title`, each line led by `indent`; the first kSummarySupports names.
void printForces(std::ostream& out, const std::string& title,
                 const std::vector<SupportReactions>& supports, const std::string& what,
                 const NoiseFloor& floor, const std::string& indent, const OutputUnits& units) {
  out << indent << title << " (force on the structure; " << units.valueIn("N", {1, "N"}).unit
      << ", " << units.valueIn("N m", {1, "N m"}).unit << ")";
  if (supports.size() > kSummarySupports)
    out << ", the first " << kSummarySupports << " of " << supports.size() << " " << what
        << " (all in results.json)";
  out << ":\n";
  // Named as in results.json and sweep.csv: fx ... mz.
  for (std::size_t i = 0; i < supports.size() && i < kSummarySupports; ++i) {
    out << indent << "  " << padded(supports[i].support, 12);
    for (const auto& [dof, value] : supports[i].components)
      out << padded(std::string(reactionName(dof)) + " " +
                        valueText(floor.load(value, isRotation(dof)),
                                  std::string(reactionUnit(dof)), units),
                    22);
    out << "\n";
  }
}

}  // namespace

void printReactions(std::ostream& out, const StaticResult& r, const NoiseFloor& floor,
                    const std::string& indent, const OutputUnits& units) {
  // A model held by springs or bearings alone has no reactions to list.
  if (!r.reactions.empty() || r.elementForces.empty())
    printForces(out, "reactions", reactionsBySupport(r), "supports", floor, indent, units);
  if (!r.elementForces.empty())
    printForces(out, "springs and bearings", forcesByName(r.elementForces), "springs and bearings",
                floor, indent, units);
}

void printPointDisplacements(std::ostream& out, const Deck& deck, const RunResult& run,
                             const StaticResult& r, const NoiseFloor& floor,
                             const std::string& indent, const OutputUnits& units) {
  const std::vector<const DeckPoint*> points = reportedPoints(deck);
  const OutputUnits::Shown length = units.valueIn("m", {1, "m"});
  const OutputUnits::Shown angle = units.valueIn("rad", {1, "rad"});
  const auto rotation = [&](double radians) {
    return valueText(floor.motion(radians, Dof::rx), "rad", units);
  };
  out << indent << "displacements at points (" << length.unit << ", " << angle.unit << "):\n";
  std::map<int, std::vector<MemberEndRotation>> ends;
  if (deck.frame && !r.hinges.empty())
    ends = memberEndRotations({*run.model, r.displacement}, r.hinges);
  for (const DeckPoint* p : points) {
    const int node = run.model->node(p->name);
    out << indent << "  " << padded(p->name, 12);
    if (deck.frame) {
      // A frame's points are places in space, not stations along one line.
      const Eigen::Vector3d& x = run.model->nodes()[node];
      std::string at = "at (" + formatValue(x.x() * length.factor) + ", " +
                       formatValue(x.y() * length.factor);
      if (deck.dimension == "3d") at += ", " + formatValue(x.z() * length.factor);
      out << padded(at + ") " + length.unit, 24);
    } else {
      out << padded("x = " + valueText(p->at, "m", units), 16);
    }
    const auto hinge = std::find_if(r.hinges.begin(), r.hinges.end(),
                                    [&](const SideRotations& h) { return h.node == node; });
    // A frame's hinged joint: each member end there turns on its own, named by its member.
    const auto memberEnds = ends.find(node);
    for (Dof d : kAllDofs) {
      if (!deck.dofs.contains(d)) continue;
      const std::string name(dofName(d));
      if (!isRotation(d) || hinge == r.hinges.end()) {
        out << padded(name + " " +
                          valueText(floor.motion(r.displacement(node, dofIndex(d)), d),
                                    motionUnit(d), units),
                      22);
        continue;
      }
      if (memberEnds != ends.end()) {
        for (const MemberEndRotation& e : memberEnds->second)
          out << padded(name + " " + e.label + " " + rotation(e.rotation[dofIndex(d) - 3]), 26);
        continue;
      }
      // A hinge: the beam end on each side turns on its own.
      for (const auto& [side, value] :
           {std::pair{" left ", &hinge->left}, std::pair{" right ", &hinge->right}})
        if (*value)
          out << padded(name + side + rotation((**value)[dofIndex(d) - 3]), 26);
    }
    out << "\n";
  }
}

}  // namespace beamrotor::cli
