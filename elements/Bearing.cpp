#include "elements/Bearing.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace beamrotor {

namespace {

std::array<double, 8> values(const BearingCoefficients& c) {
  return {c.kyy, c.kyz, c.kzy, c.kzz, c.cyy, c.cyz, c.czy, c.czz};
}

BearingCoefficients fromValues(const std::array<double, 8>& v) {
  return {v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]};
}

ElementMatrix twoByTwo(double yy, double yz, double zy, double zz) {
  ElementMatrix m(2, 2);
  m << yy, yz, zy, zz;
  return m;
}

}  // namespace

Bearing::Bearing(int node, const BearingCoefficients& c) : Bearing(node, {0.0}, {c}) {}

Bearing::Bearing(int node, std::vector<double> speeds, std::vector<BearingCoefficients> table)
    : node_(node), speeds_(std::move(speeds)), table_(std::move(table)) {
  if (speeds_.empty() || speeds_.size() != table_.size())
    throw std::invalid_argument("a bearing table needs one row of coefficients per speed");
  for (std::size_t i = 0; i < speeds_.size(); ++i) {
    if (!std::isfinite(speeds_[i]) || (i > 0 && !(speeds_[i] > speeds_[i - 1])))
      throw std::invalid_argument("bearing table speeds must be finite and strictly ascending");
    for (double v : values(table_[i]))
      if (!std::isfinite(v)) throw std::invalid_argument("bearing coefficients must be finite");
  }
}

TableBracket tableBracket(const std::vector<double>& rows, double value) {
  if (value <= rows.front()) return {0, 0.0};
  if (value >= rows.back()) return {rows.size() - 1, 0.0};
  const auto hi = std::size_t(std::upper_bound(rows.begin(), rows.end(), value) - rows.begin());
  return {hi - 1, (value - rows[hi - 1]) / (rows[hi] - rows[hi - 1])};
}

BearingCoefficients blend(const BearingCoefficients& a, const BearingCoefficients& b, double t) {
  const auto x = values(a), y = values(b);
  std::array<double, 8> v{};
  for (int i = 0; i < 8; ++i) v[i] = (1 - t) * x[i] + t * y[i];
  return fromValues(v);
}

BearingCoefficients Bearing::coefficientsAt(double speed) const {
  if (speed <= speeds_.front()) return table_.front();
  if (speed >= speeds_.back()) return table_.back();
  const TableBracket at = tableBracket(speeds_, speed);
  return blend(table_[at.low], table_[at.low + 1], at.t);
}

void Bearing::setWhirlCoefficients(std::shared_ptr<const WhirlCoefficients> whirl) {
  whirl_ = std::move(whirl);
}

EigenvalueMatrices Bearing::atEigenvalue(double speed, std::complex<double> lambda) const {
  if (!whirl_) return SpeedDependentElement::atEigenvalue(speed, lambda);
  const BearingCoefficients c = whirl_->at(speed, lambda);
  return {twoByTwo(c.kyy, c.kyz, c.kzy, c.kzz), twoByTwo(c.cyy, c.cyz, c.czy, c.czz)};
}

ElementMatrix Bearing::stiffnessAt(double speed) const {
  const BearingCoefficients c = coefficientsAt(speed);
  return twoByTwo(c.kyy, c.kyz, c.kzy, c.kzz);
}

ElementMatrix Bearing::dampingAt(double speed) const {
  const BearingCoefficients c = coefficientsAt(speed);
  if (c.cyy == 0 && c.cyz == 0 && c.czy == 0 && c.czz == 0) return {};
  return twoByTwo(c.cyy, c.cyz, c.czy, c.czz);
}

}  // namespace beamrotor
