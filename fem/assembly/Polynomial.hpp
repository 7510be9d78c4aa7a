// Polynomials in one variable by their coefficients, lowest degree first: the little algebra
// the exact extrema along elements (ElementExtrema, MemberExtrema, MemberEnvelope) need. Held
// in place, not on the heap: the extrema run this algebra for every element of every load
// combination, where a vector's allocation cost more than the arithmetic.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <initializer_list>
#include <iterator>
#include <stdexcept>

namespace beamrotor {

/// Up to N doubles in place, with the part of std::vector's interface the algebra uses. More
/// than N is a programming error (std::length_error), never a silent truncation.
template <std::size_t N>
class InPlaceDoubles {
 public:
  InPlaceDoubles() = default;
  InPlaceDoubles(std::initializer_list<double> values) : InPlaceDoubles(values.begin(), values.end()) {}
  template <class Iterator>
  InPlaceDoubles(Iterator first, Iterator last) {
    for (; first != last; ++first) push_back(*first);
  }
  /// `count` copies of `value`.
  InPlaceDoubles(std::size_t count, double value) {
    for (std::size_t k = 0; k < count; ++k) push_back(value);
  }

  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  double& operator[](std::size_t k) { return values_[k]; }
  double operator[](std::size_t k) const { return values_[k]; }
  double back() const { return values_[size_ - 1]; }
  void push_back(double v) {
    if (size_ == N) throw std::length_error("a polynomial past its fixed degree");
    values_[size_++] = v;
  }
  void pop_back() { --size_; }
  void clear() { size_ = 0; }
  /// Keeps the first n values, or appends zeros up to n.
  void resize(std::size_t n) {
    while (size_ > n) pop_back();
    while (size_ < n) push_back(0);
  }

  double* begin() { return values_.data(); }
  double* end() { return values_.data() + size_; }
  const double* begin() const { return values_.data(); }
  const double* end() const { return values_.data() + size_; }
  std::reverse_iterator<const double*> rbegin() const { return std::reverse_iterator(end()); }
  std::reverse_iterator<const double*> rend() const { return std::reverse_iterator(begin()); }

 private:
  std::array<double, N> values_{};
  std::size_t size_ = 0;
};

/// A polynomial in s by its coefficients, lowest degree first, of degree at most 10: the
/// square of a quintic (an element's translations, cubic shape functions plus a linear span
/// load's quintic) or of a cubic times a sextic (the normal stress's arc condition).
using Polynomial = InPlaceDoubles<11>;

inline double valueAt(const Polynomial& p, double s) {
  double v = 0;
  for (auto c = p.rbegin(); c != p.rend(); ++c) v = v * s + *c;
  return v;
}

inline Polynomial derivativeOf(const Polynomial& p) {
  Polynomial d;
  for (std::size_t k = 1; k < p.size(); ++k) d.push_back(double(k) * p[k]);
  return d;
}

inline Polynomial productOf(const Polynomial& a, const Polynomial& b) {
  if (a.empty() || b.empty()) return {};
  Polynomial r(a.size() + b.size() - 1, 0.0);
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = 0; j < b.size(); ++j) r[i + j] += a[i] * b[j];
  return r;
}

/// x a + y b.
inline Polynomial combination(double x, const Polynomial& a, double y, const Polynomial& b) {
  Polynomial r(std::max(a.size(), b.size()), 0.0);
  for (std::size_t k = 0; k < a.size(); ++k) r[k] += x * a[k];
  for (std::size_t k = 0; k < b.size(); ++k) r[k] += y * b[k];
  return r;
}

/// An upper bound of |p(s)| over 0 <= s <= 1: the largest |coefficient| of p in the Bernstein
/// basis of its degree, b_i = sum_{k <= i} C(i, k) / C(n, k) a_k (on [0, 1] p is a convex
/// combination of them; Farouki and Rajan, Computer Aided Geometric Design 5, 1988). Close to
/// the true largest for the low degrees here; NaN when a coefficient is.
inline double boundOnUnitInterval(const Polynomial& p) {
  if (p.empty()) return 0;
  const std::size_t n = p.size() - 1;
  double bound = 0;
  for (std::size_t i = 0; i <= n; ++i) {
    double b = 0, ratio = 1;  // C(i, k) / C(n, k), from k = 0
    for (std::size_t k = 0; k <= i; ++k) {
      b += ratio * p[k];
      if (k < i) ratio *= double(i - k) / double(n - k);
    }
    if (b != b) return b;  // NaN
    bound = std::max(bound, b < 0 ? -b : b);
  }
  return bound;
}

/// p(alpha + beta s): the polynomial in s of p read along a linear change of its variable.
inline Polynomial composedWithLine(const Polynomial& p, double alpha, double beta) {
  Polynomial r;
  for (auto c = p.rbegin(); c != p.rend(); ++c)
    r = combination(1, productOf(r, {alpha, beta}), *c, {1.0});
  return r;
}

}  // namespace beamrotor
