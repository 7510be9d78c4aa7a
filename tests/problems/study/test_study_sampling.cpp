// The random numbers, points and statistics of design studies, against closed forms: the
// normal quantile against tabulated values and its own distribution function, the Latin
// hypercube's one-point-per-stratum property, the grid's order, percentiles and the Wilson
// interval worked by hand.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>

#include "problems/study/DesignPoints.hpp"
#include "problems/study/Sampling.hpp"
#include "problems/study/StudyStatistics.hpp"

using namespace beamrotor;

TEST_SUITE("study sampling") {
  TEST_CASE("the normal quantile inverts the distribution function to round-off") {
    // Tabulated: Phi^-1(0.975) = 1.959963984540054, Phi^-1(Phi(1)) = 1, Phi^-1(0.5) = 0.
    CHECK(normalQuantile(0.975) == doctest::Approx(1.959963984540054).epsilon(1e-14));
    CHECK(normalQuantile(0.5) == doctest::Approx(0.0).epsilon(1e-15));
    CHECK(normalQuantile(normalCdf(1.0)) == doctest::Approx(1.0).epsilon(1e-14));
    // Across the range, including the far tails that a 53-bit uniform can reach (2^-54):
    // the round trip p -> x -> Phi(x) keeps p to a few ulps relative to the tail.
    for (double p : {0x1.0p-54, 1e-12, 1e-6, 0.01, 0.3, 0.7, 0.99, 1 - 1e-9}) {
      const double x = normalQuantile(p);
      const double back = p < 0.5 ? normalCdf(x) : 1 - normalCdf(-x) ;
      CAPTURE(p);
      CHECK(std::abs(back - p) <= 1e-13 * std::min(p, 1 - p) + 1e-16);
    }
  }

  TEST_CASE("uniform variates stay inside (0, 1) and indices cover their range evenly") {
    std::mt19937_64 engine(7);
    std::vector<int> counts(5, 0);
    for (int i = 0; i < 50000; ++i) {
      const double u = openUniform(engine);
      REQUIRE(u > 0);
      REQUIRE(u < 1);
      ++counts[uniformIndex(engine, 5)];
    }
    // Each count is binomial(50000, 0.2): sd = sqrt(50000 * 0.2 * 0.8) = 89; 5 sd allowed.
    for (int c : counts) CHECK(std::abs(c - 10000) < 5 * 89.5);
  }

  TEST_CASE("a Latin hypercube puts exactly one point in each stratum of each parameter") {
    DesignStudySpec spec;
    spec.sampling = StudySampling::latinHypercube;
    spec.samples = 50;
    spec.seed = 3;
    StudyDistribution normal{StudyDistribution::Kind::normal, 10, 2};
    StudyDistribution uniform{StudyDistribution::Kind::uniform, -1, 1};
    spec.parameters = {{"a", {}, normal, {}}, {"b", {}, uniform, {}}};
    const DesignPoints points(spec);
    std::set<int> strataA, strataB;
    for (long long i = 0; i < points.size(); ++i) {
      const std::vector<double> v = points.at(i);
      strataA.insert(int(normalCdf((v[0] - 10) / 2) * 50));
      strataB.insert(int((v[1] + 1) / 2 * 50));
    }
    CHECK(strataA.size() == 50);
    CHECK(strataB.size() == 50);
    // The same seed gives the same points; another seed others.
    spec.seed = 3;
    CHECK(DesignPoints(spec).at(17) == points.at(17));
    spec.seed = 4;
    CHECK(DesignPoints(spec).at(17) != points.at(17));
  }

  TEST_CASE("truncated distributions stay within their bounds and keep their shape inside") {
    StudyDistribution d{StudyDistribution::Kind::normal, 0, 1, -0.5, 2.0};
    CHECK(distributionQuantile(d, 1e-12) >= -0.5);
    CHECK(distributionQuantile(d, 1 - 1e-12) <= 2.0);
    // The median of the truncated normal: Phi(x) = (Phi(-0.5) + Phi(2)) / 2.
    const double median = normalQuantile((normalCdf(-0.5) + normalCdf(2.0)) / 2);
    CHECK(distributionQuantile(d, 0.5) == doctest::Approx(median).epsilon(1e-14));
    StudyDistribution logn{StudyDistribution::Kind::lognormal, 3.0, 0.4};
    CHECK(distributionQuantile(logn, 0.5) == doctest::Approx(3.0).epsilon(1e-14));
    CHECK(distributionQuantile(logn, normalCdf(1.0)) ==
          doctest::Approx(3.0 * std::exp(0.4)).epsilon(1e-13));
  }

  TEST_CASE("a grid runs through every combination, the last parameter fastest") {
    DesignStudySpec spec;
    spec.parameters = {{"a", {1, 2}, std::nullopt, {}}, {"b", {10, 20, 30}, std::nullopt, {}}};
    const DesignPoints points(spec);
    REQUIRE(points.size() == 6);
    CHECK(points.at(0) == std::vector<double>{1, 10});
    CHECK(points.at(2) == std::vector<double>{1, 30});
    CHECK(points.at(3) == std::vector<double>{2, 10});
    CHECK(points.at(5) == std::vector<double>{2, 30});
  }

  TEST_CASE("percentiles and the Wilson interval, worked by hand") {
    const std::vector<double> sorted{1, 2, 3, 4, 5};
    CHECK(sortedPercentile(sorted, 0.5) == 3);
    CHECK(sortedPercentile(sorted, 0.1) == doctest::Approx(1.4));  // 0.1 * 4 = 0.4 of the way
    CHECK(sortedPercentile(sorted, 1.0) == 5);
    // 0 of 10, z = 1.96: centre = (z^2/20)/(1 + z^2/10) = half width, so [0, 2 centre].
    const double z = kZ95, n = 10;
    const double centre = (z * z / (2 * n)) / (1 + z * z / n);
    const ProportionInterval none = wilsonInterval(0, 10);
    CHECK(none.low == 0);
    CHECK(none.high == doctest::Approx(2 * centre).epsilon(1e-14));
    CHECK(none.high == doctest::Approx(0.2775).epsilon(1e-3));  // the textbook figure
    // 50 of 100: symmetric about 0.5.
    const ProportionInterval half = wilsonInterval(50, 100);
    CHECK(half.low + half.high == doctest::Approx(1.0));
  }
}
