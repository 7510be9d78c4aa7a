#include "fem/assembly/MemberEnvelope.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "fem/assembly/ElementExtrema.hpp"
#include "fem/assembly/Polynomial.hpp"
#include "fem/assembly/Recovery.hpp"
#include "fem/model/LineElement.hpp"

namespace beamrotor {

namespace {

const LineElement& lineOf(const Model& model, int e) {
  const LineElement* line = asLine(model.elements().at(e));
  if (!line) throw std::invalid_argument("a member's element is not a line element");
  return *line;
}

/// The even places on an element and, for each resultant, where its largest and where its
/// smallest value over every solution lies (each solution's extremes are at an end or a zero
/// of its derivative), sorted, places closer than round-off merged. Linear in the solutions:
/// the envelope's extremes on the element are exact without evaluating every solution at every
/// other solution's stationary points.
std::vector<double> placesOn(const std::vector<std::array<Polynomial, 6>>& resultants,
                             int intervals) {
  std::vector<double> places;
  for (int k = 0; k <= intervals; ++k) places.push_back(double(k) / intervals);
  for (std::size_t c = 0; c < 6; ++c) {
    double largest = 0, smallest = 0, largestAt = 0, smallestAt = 0;
    bool first = true;
    std::vector<double> candidates;
    for (const auto& polynomials : resultants) {
      const Polynomial& p = polynomials[c];
      candidates.assign({0.0, 1.0});
      for (double s : zerosInUnitInterval(derivativeOf(p))) candidates.push_back(s);
      for (double s : candidates) {
        const double v = valueAt(p, s);
        if (first || v > largest) largest = v, largestAt = s;
        if (first || v < smallest) smallest = v, smallestAt = s;
        first = false;
      }
    }
    places.push_back(largestAt);
    places.push_back(smallestAt);
  }
  std::sort(places.begin(), places.end());
  constexpr double kSame = 1e-12;  // fractions of an element length: round-off apart
  places.erase(std::unique(places.begin(), places.end(),
                           [](double a, double b) { return b - a < kSame; }),
               places.end());
  return places;
}

}  // namespace

std::vector<EnvelopeStation> memberEnvelope(const std::vector<LoadedSolution>& solutions,
                                            const std::vector<int>& elements,
                                            int intervalsPerElement) {
  if (solutions.empty()) throw std::invalid_argument("an envelope needs at least one solution");
  std::vector<EnvelopeStation> out;
  double start = 0;
  for (int e : elements) {
    // Each solution's six resultants on this element, as polynomials in s.
    std::vector<std::array<Polynomial, 6>> resultants;
    for (const LoadedSolution& sol : solutions) {
      lineOf(*sol.model, e);  // a line element, or a clear error
      const SectionForceSeries series = sol.forceSeries(e);
      std::array<Polynomial, 6> polynomials;
      for (std::size_t c = 0; c < kForceComponents.size(); ++c)
        polynomials[c] = componentPolynomial(series, kForceComponents[c]);
      resultants.push_back(std::move(polynomials));
    }
    const double length = lineOf(*solutions.front().model, e).length();
    for (double s : placesOn(resultants, intervalsPerElement)) {
      EnvelopeStation st;
      st.element = e;
      st.s = s;
      st.along = start + s * length;
      for (std::size_t c = 0; c < 6; ++c)
        for (std::size_t k = 0; k < resultants.size(); ++k) {
          const double v = valueAt(resultants[k][c], s);
          if (k == 0 || v > st.max[c]) st.max[c] = v, st.maxBy[c] = int(k);
          if (k == 0 || v < st.min[c]) st.min[c] = v, st.minBy[c] = int(k);
        }
      out.push_back(st);
    }
    start += length;
  }
  return out;
}

}  // namespace beamrotor
