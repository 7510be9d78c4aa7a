#include "problems/study/DesignPoints.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

#include "problems/study/Sampling.hpp"

namespace beamrotor {

namespace {

/// The distribution function of d without its truncation.
double distributionCdf(const StudyDistribution& d, double x) {
  using Kind = StudyDistribution::Kind;
  if (d.kind == Kind::uniform) return std::clamp((x - d.first) / (d.second - d.first), 0.0, 1.0);
  if (d.kind == Kind::normal) return normalCdf((x - d.first) / d.second);
  return x <= 0 ? 0 : normalCdf(std::log(x / d.first) / d.second);
}

}  // namespace

double distributionQuantile(const StudyDistribution& d, double u) {
  using Kind = StudyDistribution::Kind;
  const double low = std::isfinite(d.lower) ? distributionCdf(d, d.lower) : 0.0;
  const double high = std::isfinite(d.upper) ? distributionCdf(d, d.upper) : 1.0;
  const double p = low + u * (high - low);
  double x;
  if (d.kind == Kind::uniform)
    x = d.first + p * (d.second - d.first);
  else if (d.kind == Kind::normal)
    x = d.first + d.second * normalQuantile(p);
  else
    x = d.first * std::exp(d.second * normalQuantile(p));
  return std::clamp(x, d.lower, d.upper);  // round-off at a bound never steps past it
}

DesignPoints::DesignPoints(const DesignStudySpec& spec) : count_(spec.points()) {
  for (const StudyParameter& p : spec.parameters) {
    names_.push_back(p.name);
    grid_.push_back(p.values);
  }
  if (spec.sampling == StudySampling::grid) return;
  const int dims = parameters();
  samples_.resize(std::size_t(count_) * dims);
  std::mt19937_64 engine(spec.seed);
  if (spec.sampling == StudySampling::random) {
    for (long long i = 0; i < count_; ++i)
      for (int j = 0; j < dims; ++j)
        samples_[i * dims + j] =
            distributionQuantile(*spec.parameters[j].distribution, openUniform(engine));
    return;
  }
  std::vector<long long> strata(count_);
  for (int j = 0; j < dims; ++j) {
    std::iota(strata.begin(), strata.end(), 0LL);
    for (long long k = count_ - 1; k > 0; --k)
      std::swap(strata[k], strata[uniformIndex(engine, std::uint64_t(k) + 1)]);
    for (long long i = 0; i < count_; ++i) {
      const double u = (double(strata[i]) + openUniform(engine)) / double(count_);
      samples_[i * dims + j] = distributionQuantile(*spec.parameters[j].distribution, u);
    }
  }
}

std::vector<double> DesignPoints::at(long long index) const {
  const int dims = parameters();
  std::vector<double> values(dims);
  if (!samples_.empty()) {
    std::copy_n(samples_.begin() + index * dims, dims, values.begin());
    return values;
  }
  for (int j = dims - 1; j >= 0; --j) {  // the last parameter varies fastest
    const long long n = (long long)grid_[j].size();
    values[j] = grid_[j][index % n];
    index /= n;
  }
  return values;
}

}  // namespace beamrotor
