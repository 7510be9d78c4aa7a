// One static solution along every line element as polynomials in the element fraction s: the
// six resultants (at most cubic) and the three translations (at most quintic). Recovered once
// from a solution's nodal field and span loads, or, for a combination of load cases, the
// factored sum of its cases' polynomials: the model is linear, so a combination's polynomials
// on an element are its cases' coefficient vectors weighted by the factors, a few multiply-adds
// without the element recovery (local frames, shape functions, span loads) that every
// combination repeated before. The extrema along elements and members read them through
// LoadedSolution (Recovery.hpp) when a solution carries them.
#pragma once

#include <array>
#include <memory>
#include <utility>
#include <vector>

#include "fem/assembly/Polynomial.hpp"
#include "fem/assembly/Recovery.hpp"
#include "fem/model/LineElement.hpp"

namespace beamrotor {

/// The coefficients of one line element's polynomials, lowest degree first.
struct ElementPolynomials {
  SectionForceSeries forces;                           ///< N, Vy, Vz, T, My, Mz, cubic
  std::array<std::array<double, 6>, 3> translations{};  ///< ux, uy, uz (m, global), quintic
};

/// Upper bounds of |value| along one line element (Bernstein bounds, boundOnUnitInterval) of
/// each resultant and of each translation. A sum's Bernstein coefficients are its parts'
/// summed, so a combination's bounds are at most its parts' weighted by |factor|.
struct ElementBounds {
  SectionForces forces;                  ///< of |N|, |Vy|, |Vz|, |T|, |My|, |Mz|
  std::array<double, 3> translations{};  ///< of |ux|, |uy|, |uz|
};

/// The bounds of each resultant of `forces` along the element.
SectionForces resultantBounds(const SectionForceSeries& forces);

class SolutionPolynomials {
 public:
  /// No elements (a place for sumInto).
  SolutionPolynomials() = default;
  /// Each line element's polynomials recovered from `solution` (other elements: zero).
  explicit SolutionPolynomials(const LoadedSolution& solution);
  /// The factored sum of other solutions' polynomials, all of one model (a load combination;
  /// the parts are shared, not copied).
  explicit SolutionPolynomials(
      std::vector<std::pair<std::shared_ptr<const SolutionPolynomials>, double>> parts);

  /// The number of elements (Model::elements()) it holds polynomials for.
  std::size_t elementCount() const {
    return parts_.empty() ? own_.size() : parts_.front().first->elementCount();
  }
  /// Line element `element`'s polynomials (index into Model::elements()).
  ElementPolynomials of(int element) const;
  /// Its resultants, as LineElement::sectionForceSeries gives them (of a sum, the same sums
  /// as `of`, without the translations').
  SectionForceSeries forces(int element) const;
  /// Its translations ux, uy, uz as polynomials in s (of a sum, the same sums as `of`).
  std::array<Polynomial, 3> translations(int element) const;
  /// Upper bounds of its resultants and translations along the element: of recovered
  /// polynomials their own, of a sum its parts' weighted by |factor| (no sum formed), which
  /// the extremes compare with a margin (1e-9) far above their round-off.
  ElementBounds bounds(int element) const;

  /// Every element's polynomials summed once (of each element) into `out`, whose storage is
  /// reused: a combination's extremes read each element's polynomials several times (peaks,
  /// ranges, chord deflections, largest displacement), each read then a copy instead of a
  /// factored sum. The same numbers as `of`, to the bit (the same sums in the same order).
  void sumInto(SolutionPolynomials& out) const;

 private:
  using TranslationCoefficients = std::array<std::array<double, 6>, 3>;
  /// Its translations' coefficients (of a sum, the parts' weighted, in their order).
  TranslationCoefficients translationCoefficients(int element) const;

  std::vector<ElementPolynomials> own_;  ///< recovered: by element index
  std::vector<ElementBounds> bounds_;    ///< of own_, by element index
  std::vector<std::pair<std::shared_ptr<const SolutionPolynomials>, double>> parts_;
};

/// The translations ux, uy, uz along line element `element` of `solution` (static, its span
/// load applied) recovered from the element: interpolated through six places, exact for degree
/// <= 5 (cubic shape functions plus a linear span load's quintic).
std::array<Polynomial, 3> recoveredTranslations(const LoadedSolution& solution, int element);

}  // namespace beamrotor
