#include "fem/assembly/SolutionPolynomials.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace beamrotor {

namespace {

/// Values at s = 0, 1/5, .., 1 determine a polynomial of degree <= 5 exactly.
constexpr int kDisplacementSamples = 6;

/// x += f y, resultant by resultant.
void addScaled(SectionForces& x, double f, const SectionForces& y) {
  x.N += f * y.N;
  x.Vy += f * y.Vy;
  x.Vz += f * y.Vz;
  x.T += f * y.T;
  x.My += f * y.My;
  x.Mz += f * y.Mz;
}

/// The bounds of own polynomials.
ElementBounds boundsOf(const ElementPolynomials& p) {
  ElementBounds out;
  out.forces = resultantBounds(p.forces);
  for (std::size_t c = 0; c < 3; ++c)
    out.translations[c] =
        boundOnUnitInterval(Polynomial(p.translations[c].begin(), p.translations[c].end()));
  return out;
}

}  // namespace

SectionForces resultantBounds(const SectionForceSeries& forces) {
  const auto bound = [&](double SectionForces::*f) {
    Polynomial p;
    for (const SectionForces& c : forces.c) p.push_back(c.*f);
    return boundOnUnitInterval(p);
  };
  return {bound(&SectionForces::N), bound(&SectionForces::Vy), bound(&SectionForces::Vz),
          bound(&SectionForces::T), bound(&SectionForces::My), bound(&SectionForces::Mz)};
}

std::array<Polynomial, 3> recoveredTranslations(const LoadedSolution& solution, int element) {
  using Square = Eigen::Matrix<double, kDisplacementSamples, kDisplacementSamples>;
  // The Vandermonde matrix of the places, decomposed once for every element.
  static const Eigen::FullPivLU<Square> vandermonde = [] {
    Square V;
    for (int i = 0; i < kDisplacementSamples; ++i)
      for (int k = 0; k < kDisplacementSamples; ++k)
        V(i, k) = std::pow(double(i) / (kDisplacementSamples - 1), k);
    return V.fullPivLu();
  }();
  const LineElement& line = *asLine(solution.model->elements().at(element));
  const ElementVector u = elementValues(line, *solution.displacement);
  const ElementSpanLoad q = solution.spanOn(element, line);
  Eigen::Matrix<double, kDisplacementSamples, 3> values;
  for (int i = 0; i < kDisplacementSamples; ++i) {
    const auto d = line.displacementAt(u, double(i) / (kDisplacementSamples - 1), q);
    for (int c = 0; c < 3; ++c) values(i, c) = d[c];
  }
  const Eigen::Matrix<double, kDisplacementSamples, 3> coefficients = vandermonde.solve(values);
  std::array<Polynomial, 3> out;
  for (int c = 0; c < 3; ++c)
    out[c] = Polynomial(coefficients.col(c).data(), coefficients.col(c).data() + kDisplacementSamples);
  return out;
}

SolutionPolynomials::SolutionPolynomials(const LoadedSolution& solution) {
  if (solution.polynomials)
    throw std::invalid_argument("recovering polynomials from a solution that carries them");
  const auto& elements = solution.model->elements();
  own_.resize(elements.size());
  bounds_.resize(elements.size());
  for (int e = 0; e < int(elements.size()); ++e) {
    if (!asLine(elements[e])) continue;
    own_[e].forces = solution.forceSeries(e);
    const std::array<Polynomial, 3> u = recoveredTranslations(solution, e);
    for (std::size_t c = 0; c < 3; ++c) std::copy(u[c].begin(), u[c].end(), own_[e].translations[c].begin());
    bounds_[e] = boundsOf(own_[e]);
  }
}

SolutionPolynomials::SolutionPolynomials(
    std::vector<std::pair<std::shared_ptr<const SolutionPolynomials>, double>> parts)
    : parts_(std::move(parts)) {
  for (const auto& [part, factor] : parts_)
    if (!part) throw std::invalid_argument("a combination's part has no polynomials");
}

ElementPolynomials SolutionPolynomials::of(int element) const {
  if (parts_.empty()) return own_.at(element);
  return {forces(element), translationCoefficients(element)};
}

SectionForceSeries SolutionPolynomials::forces(int element) const {
  if (parts_.empty()) return own_.at(element).forces;
  SectionForceSeries sum;
  for (const auto& [part, factor] : parts_) {
    const SectionForceSeries p = part->forces(element);
    for (std::size_t k = 0; k < sum.c.size(); ++k) addScaled(sum.c[k], factor, p.c[k]);
  }
  return sum;
}

SolutionPolynomials::TranslationCoefficients SolutionPolynomials::translationCoefficients(
    int element) const {
  if (parts_.empty()) return own_.at(element).translations;
  TranslationCoefficients sum{};
  for (const auto& [part, factor] : parts_) {
    const TranslationCoefficients p = part->translationCoefficients(element);
    for (std::size_t c = 0; c < 3; ++c)
      for (std::size_t k = 0; k < 6; ++k) sum[c][k] += factor * p[c][k];
  }
  return sum;
}

std::array<Polynomial, 3> SolutionPolynomials::translations(int element) const {
  const TranslationCoefficients t = translationCoefficients(element);
  std::array<Polynomial, 3> out;
  for (int c = 0; c < 3; ++c) out[c] = Polynomial(t[c].begin(), t[c].end());
  return out;
}

ElementBounds SolutionPolynomials::bounds(int element) const {
  if (parts_.empty()) return bounds_.at(element);
  ElementBounds sum;
  for (const auto& [part, factor] : parts_) {
    const ElementBounds p = part->bounds(element);
    addScaled(sum.forces, std::abs(factor), p.forces);
    for (std::size_t c = 0; c < 3; ++c) sum.translations[c] += std::abs(factor) * p.translations[c];
  }
  return sum;
}

void SolutionPolynomials::sumInto(SolutionPolynomials& out) const {
  out.parts_.clear();
  const std::size_t count = elementCount();
  out.own_.resize(count);
  out.bounds_.resize(count);
  for (std::size_t e = 0; e < count; ++e) {
    out.own_[e] = of(int(e));
    out.bounds_[e] = boundsOf(out.own_[e]);
  }
}

}  // namespace beamrotor
