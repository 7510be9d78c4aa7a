#include "elements/WhirlTable.hpp"

#include <cmath>
#include <stdexcept>

namespace beamrotor {

namespace {

void checkAscending(const std::vector<double>& v, const char* what) {
  if (v.empty()) throw std::invalid_argument(std::string("a whirl table needs ") + what);
  for (std::size_t i = 0; i < v.size(); ++i)
    if (!std::isfinite(v[i]) || (i > 0 && !(v[i] > v[i - 1])))
      throw std::invalid_argument(std::string("a whirl table's ") + what +
                                  " must be finite and strictly ascending");
}

}  // namespace

WhirlTable::WhirlTable(std::vector<double> speeds, std::vector<double> whirls,
                       std::vector<BearingCoefficients> rows)
    : speeds_(std::move(speeds)), whirls_(std::move(whirls)), rows_(std::move(rows)) {
  checkAscending(speeds_, "speeds");
  checkAscending(whirls_, "whirl frequencies");
  if (rows_.size() != speeds_.size() * whirls_.size())
    throw std::invalid_argument("a whirl table needs one row per speed and whirl frequency");
}

BearingCoefficients WhirlTable::atRow(std::size_t s, double whirl) const {
  const std::size_t n = whirls_.size();
  const TableBracket w = tableBracket(whirls_, whirl);
  if (w.t == 0) return rows_[s * n + w.low];
  return blend(rows_[s * n + w.low], rows_[s * n + w.low + 1], w.t);
}

BearingCoefficients WhirlTable::atWhirl(double speed, double whirl) const {
  const TableBracket s = tableBracket(speeds_, speed);
  if (s.t == 0) return atRow(s.low, whirl);
  return blend(atRow(s.low, whirl), atRow(s.low + 1, whirl), s.t);
}

BearingCoefficients WhirlTable::at(double speed, std::complex<double> lambda) const {
  return atWhirl(speed, std::abs(lambda.imag()));
}

std::vector<BearingCoefficients> WhirlTable::synchronous() const {
  std::vector<BearingCoefficients> out;
  for (std::size_t s = 0; s < speeds_.size(); ++s) out.push_back(atRow(s, speeds_[s]));
  return out;
}

}  // namespace beamrotor
