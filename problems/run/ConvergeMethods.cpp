#include "problems/run/ConvergeMethods.hpp"

#include <cmath>

namespace beamrotor {

std::vector<ConvergeMethod> convergeMethods(bool massMatters) {
  std::vector<ConvergeMethod> methods{{"eb-consistent", "Euler-Bernoulli, consistent mass",
                                       BeamTheory::eulerBernoulli, MassModel::consistent}};
  if (massMatters)
    methods.push_back({"eb-lumped", "Euler-Bernoulli, lumped mass", BeamTheory::eulerBernoulli,
                       MassModel::lumped});
  methods.push_back(
      {"timoshenko", "Timoshenko, locking-free", BeamTheory::timoshenko, MassModel::consistent});
  methods.push_back({"timoshenko-linear-full", "Timoshenko linear, full integration (locks)",
                     BeamTheory::timoshenkoLinearFullIntegration, MassModel::consistent});
  methods.push_back({"timoshenko-linear-reduced", "Timoshenko linear, reduced integration",
                     BeamTheory::timoshenkoLinearReducedIntegration, MassModel::consistent});
  return methods;
}

void useMethod(const ConvergeMethod& method, Deck& deck) {
  deck.beam.theory = method.theory;
  deck.beam.mass = method.mass;
  for (DeckSegment& s : deck.segments) {
    s.options.theory = method.theory;
    s.options.mass = method.mass;
  }
  for (TrainShaft& shaft : deck.train.shafts)
    for (Segment& s : shaft.segments) {
      s.options.theory = method.theory;
      s.options.mass = method.mass;
    }
}

void refineMesh(Deck& deck, int level) {
  const int factor = 1 << level;
  for (std::size_t i = 0; i < deck.segments.size(); ++i) {
    DeckSegment& s = deck.segments[i];
    // A tension- or compression-only member is one element, exact without span loads (which
    // it refuses): it goes slack as a whole.
    if (deck.frame && i < deck.frame->members.size() &&
        deck.frame->members[i].acts != MemberAction::both)
      continue;
    if (s.elements > 0)
      s.elements *= factor;
    else
      s.size /= factor;
  }
  for (TrainShaft& shaft : deck.train.shafts)
    for (Segment& s : shaft.segments) {
      if (s.elements > 0)
        s.elements *= factor;
      else
        s.targetSize /= factor;
    }
}

void refineTimeStep(Deck& deck, int level) {
  for (DeckAnalysis& a : deck.analyses)
    if (auto* transient = a.as<TransientSpec>()) transient->run.dt /= double(1 << level);
}

}  // namespace beamrotor
