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

BearingCoefficients Bearing::coefficientsAt(double speed) const {
  if (speed <= speeds_.front()) return table_.front();
  if (speed >= speeds_.back()) return table_.back();
  const auto hi = std::upper_bound(speeds_.begin(), speeds_.end(), speed) - speeds_.begin();
  const double t = (speed - speeds_[hi - 1]) / (speeds_[hi] - speeds_[hi - 1]);
  const auto a = values(table_[hi - 1]), b = values(table_[hi]);
  std::array<double, 8> v{};
  for (int i = 0; i < 8; ++i) v[i] = (1 - t) * a[i] + t * b[i];
  return fromValues(v);
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
