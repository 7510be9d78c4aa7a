#include "problems/study/StudySummary.hpp"

#include <algorithm>
#include <cmath>

#include "problems/deck/ShownFieldUnit.hpp"
#include "problems/study/StudyStatistics.hpp"

namespace beamrotor {

namespace {

constexpr std::size_t kFailuresListed = 20;

const char* samplingName(StudySampling s) {
  return s == StudySampling::grid ? "grid" : s == StudySampling::random ? "random"
                                                                          : "latin-hypercube";
}

const char* distributionName(StudyDistribution::Kind k) {
  return k == StudyDistribution::Kind::uniform  ? "uniform"
         : k == StudyDistribution::Kind::normal ? "normal"
                                                : "lognormal";
}

Json proportionJson(long long count, long long trials) {
  const ProportionInterval p = wilsonInterval(count, trials);
  return Json{{"count", count}, {"trials", trials}, {"probability", p.estimate},
              {"wilson95", {p.low, p.high}}};
}

Json pointParametersJson(const StudyPlan& plan, const std::vector<double>& values) {
  Json j = Json::object();
  for (std::size_t k = 0; k < values.size(); ++k) j[plan.parameterNames[k]] = values[k];
  return j;
}

}  // namespace

StudySummary::StudySummary(const StudyPlan& plan)
    : plan_(plan), outputs_(plan.spec.outputs.size()), checks_(plan.checkNames.size()) {}

void StudySummary::add(const StudyRow& row) {
  ++points_;
  if (!row.ok()) {
    ++failed_;
    if (failures_.size() < kFailuresListed) failures_.push_back({row.index, row.status, row.parameters});
  }
  for (std::size_t k = 0; k < outputs_.size(); ++k) {
    const double v = row.outputs[k];
    if (std::isnan(v)) continue;
    OutputTally& t = outputs_[k];
    t.values.push_back(v);
    const double delta = v - t.mean;
    t.mean += delta / double(t.values.size());
    t.m2 += delta * (v - t.mean);
    const StudyOutput& o = plan_.spec.outputs[k];
    // Largest value for an upper limit, smallest for a lower one, largest magnitude without.
    const double badness = !o.limit ? std::abs(v) : o.lowerLimit ? -v : v;
    if (t.worst < 0 || badness > t.worstValue) {
      t.worst = row.index;
      t.worstValue = badness;
      t.worstActual = v;
      t.worstParameters = row.parameters;
    }
    if (o.violates(v)) ++t.exceeded;
  }
  for (std::size_t k = 0; k < checks_.size(); ++k) {
    if (row.passed[k] < 0) continue;
    ++checks_[k].applicable;
    checks_[k].passed += row.passed[k];
  }
}

std::optional<std::pair<long long, std::vector<double>>> StudySummary::worstPoint() const {
  int chosen = -1;
  double ratio = -INFINITY;
  for (std::size_t k = 0; k < outputs_.size(); ++k) {
    const StudyOutput& o = plan_.spec.outputs[k];
    if (!o.limit || outputs_[k].worst < 0 || *o.limit == 0) continue;
    // value / |limit| for an upper limit; for a lower one the same mirrored about the limit
    // (2 limit - value) / |limit|: 1 at a positive limit either way, growing past it.
    const double L = *o.limit;
    const double r = o.lowerLimit ? (2 * L + outputs_[k].worstValue) / std::abs(L)
                                  : outputs_[k].worstValue / std::abs(L);
    if (r > ratio) {
      ratio = r;
      chosen = int(k);
    }
  }
  if (chosen < 0)
    for (std::size_t k = 0; k < outputs_.size() && chosen < 0; ++k)
      if (outputs_[k].worst >= 0) chosen = int(k);
  if (chosen < 0) return std::nullopt;
  return std::make_pair(outputs_[chosen].worst, outputs_[chosen].worstParameters);
}

Json StudySummary::json() const {
  const DesignStudySpec& spec = plan_.spec;
  const bool sampled = spec.sampling != StudySampling::grid;
  Json j;
  j["deck"] = plan_.deckPath;
  j["sampling"] = samplingName(spec.sampling);
  if (sampled) j["seed"] = spec.seed;
  j["points"] = points_;
  j["failed"] = failed_;
  Json parameters = Json::array();
  for (std::size_t k = 0; k < spec.parameters.size(); ++k) {
    const StudyParameter& p = spec.parameters[k];
    Json one{{"name", p.name}, {"unit", bareUnitName(plan_.parameterUnits.at(k))}};
    if (p.distribution) {
      const StudyDistribution& d = *p.distribution;
      one["distribution"] = distributionName(d.kind);
      one["parameters"] = {d.first, d.second};
      if (std::isfinite(d.lower)) one["lower"] = d.lower;
      if (std::isfinite(d.upper)) one["upper"] = d.upper;
    } else {
      one["values"] = p.values.size();
      one["from"] = p.values.front();
      one["to"] = p.values.back();
    }
    parameters.push_back(one);
  }
  j["parameters"] = parameters;
  Json outputs = Json::array();
  for (std::size_t k = 0; k < outputs_.size(); ++k) {
    const OutputTally& t = outputs_[k];
    const StudyOutput& o = spec.outputs[k];
    Json one{{"name", o.text},
             {"unit", bareUnitName(plan_.outputUnits.at(k))},
             {"analysis", o.analysis},
             {"count", t.values.size()}};
    if (o.limit) one["limit"] = *o.limit;
    if (o.lowerLimit) one["limit_is"] = "lower";
    if (!t.values.empty()) {
      std::vector<double> sorted = t.values;
      std::sort(sorted.begin(), sorted.end());
      one["min"] = sorted.front();
      one["max"] = sorted.back();
      one["mean"] = t.mean;
      one["sd"] = t.values.size() > 1 ? std::sqrt(t.m2 / double(t.values.size() - 1)) : 0.0;
      Json percentiles;
      for (int p : {1, 5, 25, 50, 75, 95, 99}) {
        std::string key = "p";  // appended, not "p" + temporary: GCC 12's false -Wrestrict
        key += std::to_string(p);
        percentiles[key] = sortedPercentile(sorted, p / 100.0);
      }
      one["percentiles"] = percentiles;
      one["worst"] = {{"point", t.worst},
                      {"value", t.worstActual},
                      {"parameters", pointParametersJson(plan_, t.worstParameters)}};
      if (o.limit) {
        one["exceeded"] = t.exceeded;
        if (sampled) one["exceedance"] = proportionJson(t.exceeded, (long long)t.values.size());
      }
    }
    outputs.push_back(one);
  }
  j["outputs"] = outputs;
  Json checks = Json::array();
  for (std::size_t k = 0; k < checks_.size(); ++k) {
    const CheckTally& t = checks_[k];
    Json one{{"name", plan_.checkNames[k]},
             {"unit", bareUnitName(plan_.checkUnits.at(k))},
             {"applicable", t.applicable},
             {"passed", t.passed}};
    if (t.applicable > 0) {
      one["pass_rate"] = double(t.passed) / double(t.applicable);
      if (sampled) one["failure"] = proportionJson(t.applicable - t.passed, t.applicable);
    }
    checks.push_back(one);
  }
  j["checks"] = checks;
  if (auto worst = worstPoint())
    j["worst_point"] = {{"point", worst->first},
                        {"parameters", pointParametersJson(plan_, worst->second)}};
  Json failures = Json::array();
  for (const Failure& f : failures_)
    failures.push_back({{"point", f.index},
                        {"parameters", pointParametersJson(plan_, f.parameters)},
                        {"status", f.status}});
  j["failures"] = failures;
  return j;
}

}  // namespace beamrotor
