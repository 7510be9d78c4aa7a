#include "fem/static/TrainEnvelope.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "fem/assembly/ElementExtrema.hpp"

namespace beamrotor {

namespace {

/// Relative size below which an extreme is the round-off of zero: far above the few ulps a
/// cubic's evaluation loses, far below any effect a load on the path has.
constexpr double kRoundOffOfZero = 1e-12;

}  // namespace

double trainEffect(const InfluenceLine& line, const std::vector<TrainLoad>& train, double lead) {
  double sum = 0;
  for (const TrainLoad& load : train) {
    const double s = lead - load.offset;
    if (s >= 0 && s <= line.length()) sum += load.force * line.at(s);
  }
  return sum;
}

TrainEnvelope trainEnvelope(const InfluenceLine& line, const std::vector<TrainLoad>& train) {
  double longest = 0;
  for (const TrainLoad& load : train) longest = std::max(longest, load.offset);
  const double end = line.length() + longest;
  std::vector<double> knots;
  for (const TrainLoad& load : train)
    for (double b : line.breaks)
      if (b + load.offset >= 0 && b + load.offset <= end) knots.push_back(b + load.offset);
  knots.push_back(0);
  knots.push_back(end);
  std::sort(knots.begin(), knots.end());
  knots.erase(std::unique(knots.begin(), knots.end()), knots.end());

  TrainEnvelope out;
  out.max.value = -std::numeric_limits<double>::infinity();
  out.min.value = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k + 1 < knots.size(); ++k) {
    const double x0 = knots[k], x1 = knots[k + 1], width = x1 - x0;
    if (!(width > 0)) continue;
    const double middle = 0.5 * (x0 + x1);
    // The effect on [x0, x1] as a polynomial in u = (x - x0) / width.
    Polynomial effect;
    for (const TrainLoad& load : train) {
      const double s = middle - load.offset;
      if (s < 0 || s > line.length()) continue;
      const std::size_t p = line.pieceAt(s);
      const double piece = line.breaks[p + 1] - line.breaks[p];
      effect = combination(1, effect, load.force,
                           composedWithLine(line.pieces[p],
                                            (x0 - load.offset - line.breaks[p]) / piece,
                                            width / piece));
    }
    std::vector<double> places;
    appendZeros(derivativeOf(effect), places);
    places.push_back(0);
    places.push_back(1);
    for (double u : places) {
      const double value = effect.empty() ? 0 : valueAt(effect, u);
      const double lead = x0 + u * width;
      if (value > out.max.value) out.max = {value, lead};
      if (value < out.min.value) out.min = {value, lead};
    }
  }
  // An extreme within the round-off of the largest effect the train could have (every load at
  // the line's largest value) is that round-off of 0, e.g. the train standing off the path or
  // on a support: it is reported as 0.
  double largest = 0;  // |line| <= the sum of a piece's |coefficients| on [0, 1]
  for (const Polynomial& piece : line.pieces) {
    double bound = 0;
    for (double c : piece) bound += std::abs(c);
    largest = std::max(largest, bound);
  }
  double forces = 0;
  for (const TrainLoad& load : train) forces += std::abs(load.force);
  const double noise = kRoundOffOfZero * forces * largest;
  for (TrainExtreme* e : {&out.max, &out.min})
    if (std::abs(e->value) <= noise) e->value = 0;
  return out;
}

NodalField trainDisplacement(const PathUnitLoads& units, const std::vector<TrainLoad>& train,
                             double lead) {
  if (units.solved.empty()) throw std::invalid_argument("a path without unit loads");
  NodalField out = NodalField::Zero(units.solved.front().displacement.rows(), kDofKinds);
  for (const TrainLoad& load : train) {
    double s = lead - load.offset;
    if (s < 0 || s > units.length()) continue;
    // The path element holding s (the later one at a node: both give the node's loads).
    std::size_t e = 0;
    while (e + 1 < units.lines.size() && s >= units.lines[e]->length()) {
      s -= units.lines[e]->length();
      ++e;
    }
    const double L = units.lines[e]->length();
    const double along = std::clamp(s / L, 0.0, 1.0);
    const double xi = units.path[e].reversed ? 1 - along : along;
    for (const auto& [c, share] : units.shares[e])
      out += load.force * valueAt(share, xi) * units.solved[std::size_t(c)].displacement;
  }
  return out;
}

}  // namespace beamrotor
