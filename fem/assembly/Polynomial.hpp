// Polynomials in one variable by their coefficients, lowest degree first: the little algebra
// the exact extrema along elements (ElementExtrema, MemberExtrema) need.
#pragma once

#include <algorithm>
#include <vector>

namespace beamrotor {

/// A polynomial in s by its coefficients, lowest degree first.
using Polynomial = std::vector<double>;

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

/// p(alpha + beta s): the polynomial in s of p read along a linear change of its variable.
inline Polynomial composedWithLine(const Polynomial& p, double alpha, double beta) {
  Polynomial r;
  for (auto c = p.rbegin(); c != p.rend(); ++c)
    r = combination(1, productOf(r, {alpha, beta}), *c, {1.0});
  return r;
}

}  // namespace beamrotor
