// Influence lines of a two-span continuous beam against the Mueller-Breslau closed forms, at
// nodes and inside elements (also the elements where a resultant is read, whose clamped
// share the lines add), a path read backwards, and the envelope of a two-wheel crane trolley
// against the textbook position rule.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

#include "fem/assembly/Recovery.hpp"
#include "fem/static/InfluenceLines.hpp"
#include "fem/static/TrainEnvelope.hpp"
#include "tests/Helpers.hpp"

using namespace beamrotor;
using namespace beamrotor::test;

namespace influence_lines {

// The consistent nodal loads of Euler-Bernoulli elements give exact nodal values, and the
// clamped share is a closed form: the lines are exact, so only round-off separates them from
// the closed forms (values of order 1 and L; 1e-9 leaves room for K's conditioning).
constexpr double kInfluenceExact = 1e-9;

/// Two equal spans L on three pins (A at 0, B at L, C at 2L), n elements per span.
struct TwoSpans {
  Model model;
  Line line;
  double L = 0;
  int n = 0;
  TwoSpans(double span, int perSpan) : L(span), n(perSpan) {
    line = uniformBeam(model, 2 * L, steelRectangle(0.1, 0.2), 2 * n);
    model.addSupport({"A", line.nodes[0], {{Dof::ux, 0}, {Dof::uy, 0}}});
    model.addSupport({"B", line.nodes[std::size_t(n)], {{Dof::uy, 0}}});
    model.addSupport({"C", line.nodes[std::size_t(2 * n)], {{Dof::uy, 0}}});
  }
  /// The element index of the k-th beam from the start.
  int element(int k) const {
    for (std::size_t e = 0; e < model.elements().size(); ++e)
      if (model.elements()[e].get() == line.beams[std::size_t(k)]) return int(e);
    return -1;
  }
  std::vector<PathElement> path(bool backwards) const {
    std::vector<PathElement> p;
    for (int k = 0; k < 2 * n; ++k) p.push_back({element(k), false});
    if (backwards) {
      std::reverse(p.begin(), p.end());
      for (PathElement& e : p) e.reversed = true;
    }
    return p;
  }
  /// Mz at the start of the k-th beam.
  InfluenceQuantity momentAtStartOf(int k) const {
    const int e = element(k);
    const LineElement* beam = asLine(model.elements()[std::size_t(e)]);
    return {[beam](const StaticResult& r) {
              return beam->sectionForceSeries(elementValues(*beam, r.displacement), {}).at(0).Mz;
            },
            e, 0, ForceComponent::Mz};
  }
};

/// Mueller-Breslau for two equal spans, a downward unit load at x: the reaction at B (up), and
/// the sagging moments at B and at the middle of the first span.
struct TwoSpanLines {
  double reactionB, momentB, momentMid;
};
TwoSpanLines closedForm(double L, double x) {
  const bool first = x <= L;
  const double xi = first ? x / L : (2 * L - x) / L;  // from the outer support of its span
  const double rB = xi * (3 - xi * xi) / 2;
  const double mB = -L * xi * (1 - xi * xi) / 4;
  const double rA = first ? (2 - xi - rB) / 2 : mB / L;
  const double mMid = rA * L / 2 - (first ? std::max(0.0, L / 2 - x) : 0.0);
  return {rB, mB, mMid};
}


TEST_SUITE("influence lines") {
  TEST_CASE("two-span beam: reaction and moments against Mueller-Breslau, inside elements too") {
    for (bool backwards : {false, true}) {
      CAPTURE(backwards);
      const TwoSpans beam(6.0, 6);
      std::vector<InfluenceQuantity> q{
          {[](const StaticResult& s) { return s.reaction("B", Dof::uy); }},
          beam.momentAtStartOf(beam.n),      // at B, read in the first element of span 2
          beam.momentAtStartOf(beam.n / 2),  // mid-span 1, read in the element after it
      };
      const auto lines = influenceLines(beam.model, beam.path(backwards), {0, -1, 0}, q);
      REQUIRE(lines.size() == 3);
      const double total = 2 * beam.L;
      CHECK(lines[0].length() == doctest::Approx(total));
      // The code's Mz is the sagging moment with the opposite sign or the same: fixed once by
      // the value at mid-span under a load there, which sags (closed form 0.203 L > 0).
      const double sag = lines[2].at(backwards ? total - beam.L / 2 : beam.L / 2) > 0 ? 1 : -1;
      double worst = 0;
      for (int i = 1; i < 240; ++i) {  // 240 / 12 elements: 20 places per element, not at nodes
        const double x = total * i / 240.0 + 1e-3;
        if (x >= total) continue;
        const double s = backwards ? total - x : x;
        const TwoSpanLines ref = closedForm(beam.L, x);
        worst = std::max({worst, std::abs(lines[0].at(s) - ref.reactionB),
                          std::abs(sag * lines[1].at(s) - ref.momentB) / beam.L,
                          std::abs(sag * lines[2].at(s) - ref.momentMid) / beam.L});
      }
      MESSAGE("largest error against the closed forms: " << worst);
      CHECK(worst < kInfluenceExact);
    }
  }

  TEST_CASE("crane girder: two equal wheels at spacing a against the position rule") {
    // Simply supported span L = 10 m, wheels P = 1 at a = 2 m: the largest moment anywhere
    // lies under a wheel placed so that mid-span halves the distance between that wheel and
    // the resultant, at x = L/2 - a/4 = 4.5 m: M = P (L/2 - a/4)^2 * 2 / L = 4.05 P m (beats
    // one wheel at mid-span, P L / 4 = 2.5 P m).
    Model model;
    const double L = 10, a = 2;
    const Line line = uniformBeam(model, L, steelRectangle(0.1, 0.3), 20);
    model.addSupport({"A", line.nodes.front(), {{Dof::ux, 0}, {Dof::uy, 0}}});
    model.addSupport({"B", line.nodes.back(), {{Dof::uy, 0}}});
    std::vector<PathElement> path;
    int at = -1;  // the element starting at 4.5 m
    for (std::size_t k = 0; k < line.beams.size(); ++k)
      for (std::size_t e = 0; e < model.elements().size(); ++e)
        if (model.elements()[e].get() == line.beams[k]) {
          path.push_back({int(e), false});
          if (k == 9) at = int(e);
        }
    const LineElement* beam = asLine(model.elements()[std::size_t(at)]);
    const InfluenceQuantity moment{
        [beam](const StaticResult& r) {
          return beam->sectionForceSeries(elementValues(*beam, r.displacement), {}).at(0).Mz;
        },
        at, 0, ForceComponent::Mz};
    const InfluenceLine line45 = influenceLines(model, path, {0, -1, 0}, {moment}).front();
    const double sag = line45.at(4.5) > 0 ? 1 : -1;
    const TrainEnvelope both = trainEnvelope(line45, {{1, 0}, {1, a}});
    const TrainExtreme worst = sag > 0 ? both.max : both.min;
    const double rule = (L / 2 - a / 4) * (L / 2 - a / 4) * 2 / L;
    MESSAGE("two wheels: " << sag * worst.value << " N m at lead " << worst.lead << " m; rule "
                           << rule);
    CHECK(std::abs(sag * worst.value - rule) < kInfluenceExact * rule);
    CHECK(worst.lead == doctest::Approx(4.5 + a).epsilon(1e-9));  // the second wheel at 4.5 m

    // A second method: the effect sampled at 12001 positions of the train never passes the
    // exact extremes (beyond round-off), and comes within the sampling's reach of them (the
    // effect's slope is at most 2 P per metre, the samples 1 mm apart).
    double sampledMax = -1e300, sampledMin = 1e300;
    for (int i = 0; i <= 12000; ++i) {
      const double effect = trainEffect(line45, {{1, 0}, {1, a}}, (L + a) * i / 12000.0);
      sampledMax = std::max(sampledMax, effect);
      sampledMin = std::min(sampledMin, effect);
    }
    CHECK(sampledMax <= both.max.value + kInfluenceExact);
    CHECK(sampledMin >= both.min.value - kInfluenceExact);
    CHECK(std::max(both.max.value - sampledMax, sampledMin - both.min.value) < 2e-3);

    // One wheel: the envelope is the influence line's own extremes, 4.5 * 5.5 / 10 at 4.5 m.
    const TrainEnvelope one = trainEnvelope(line45, {{1, 0}});
    const TrainExtreme peak = sag > 0 ? one.max : one.min;
    CHECK(std::abs(sag * peak.value - 4.5 * 5.5 / L) < kInfluenceExact);
    CHECK(peak.lead == doctest::Approx(4.5).epsilon(1e-9));
    CHECK(std::abs(sag > 0 ? one.min.value : one.max.value) < kInfluenceExact);  // nothing hogs
  }
}

}  // namespace influence_lines
