// summary.json of a design study, gathered row by row in point order (so a threaded or MPI
// study sums in the serial order and gives the same file):
//   {deck, sampling, seed, points, failed, parameters [{name, unit, values | distribution}],
//    outputs [{name, unit, analysis, count, limit?, limit_is? ("lower"), min, max, mean, sd,
//              percentiles {p1 .. p99}, worst {point, value, parameters {}}, exceeded?,
//              exceedance? {count, probability, wilson95}}],
//    checks [{name, unit, applicable, passed, pass_rate, failure? {count, trials, probability,
//             wilson95}}],
//    worst_point {point, parameters, why}, failures [first 20 {point, parameters, status}]}
// The worst point of an output is where it is largest (with an upper limit), smallest (with a
// lower one) or largest in magnitude (without); the study's worst point is the worst of the
// output nearest its limit (largest value / |limit|, for a lower limit (2 limit - value) /
// |limit|), or without limits the first output's. `exceeded` counts the points beyond the
// limit (above an upper, below a lower one). Sampled studies also give, for each limit and
// check, the probability of passing the limit or failing the check with its Wilson 95 %
// interval.
// Every number is in its column's unit of study.csv (SI, rpm for a critical speed or a bare
// *_rpm parameter), named by `unit` ("" when dimensionless); the output units chosen change
// only the printed summary and the worst point's directory.
// Memory: one double per output per point (for the percentiles), the rest is counters.
#pragma once

#include <optional>
#include <vector>

#include "problems/output/JsonWriter.hpp"
#include "problems/study/StudyPoint.hpp"

namespace beamrotor {

class StudySummary {
 public:
  explicit StudySummary(const StudyPlan& plan);
  /// Rows must come in point order.
  void add(const StudyRow& row);
  /// The study's worst point (index and parameter values), if any point succeeded.
  std::optional<std::pair<long long, std::vector<double>>> worstPoint() const;
  Json json() const;
  long long failed() const { return failed_; }
  long long points() const { return points_; }

 private:
  struct OutputTally {
    std::vector<double> values;
    double mean = 0, m2 = 0;  // Welford's running mean and sum of squared deviations
    long long worst = -1;
    double worstValue = 0;   // what made it worst: the value, or its magnitude
    double worstActual = 0;  // the value itself
    std::vector<double> worstParameters;
    long long exceeded = 0;
  };
  struct CheckTally {
    long long applicable = 0, passed = 0;
  };
  const StudyPlan& plan_;
  std::vector<OutputTally> outputs_;
  std::vector<CheckTally> checks_;
  long long points_ = 0, failed_ = 0;
  struct Failure {
    long long index = 0;
    std::string status;
    std::vector<double> parameters;
  };
  std::vector<Failure> failures_;  ///< the first few
};

}  // namespace beamrotor
