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

/// The even places and the stationary points of every solution's resultants on element e,
/// sorted, places closer than round-off merged.
std::vector<double> placesOn(const std::vector<std::array<Polynomial, 6>>& resultants,
                             int intervals) {
  std::vector<double> places;
  for (int k = 0; k <= intervals; ++k) places.push_back(double(k) / intervals);
  for (const auto& polynomials : resultants)
    for (const Polynomial& p : polynomials)
      for (double s : zerosInUnitInterval(derivativeOf(p))) places.push_back(s);
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
