// Several excitation orders on one Campbell diagram (`order: [1, 0.5, 2]`), through the deck
// path, on the shipped forme-shaft rotor in its rigid limit (E = 2e17, bearings placed so that
// C1 l1 = C2 l2): its bounce line is then sqrt((C1 + C2) / m) at every speed (problems/scenes/
// README.md, forme shaft), so the n x speed line meets it at exactly bounce / n. The deck's own
// checks hold the order-1 crossing to 1e-6 (the finite E of the rigid limit); the same bound
// holds here, since a constant line makes the crossing's linear interpolation exact.
#include <doctest/doctest.h>

#include <cmath>
#include <string>

#include "problems/run/Study.hpp"
#include "tests/problems/DeckTestSupport.hpp"

using namespace beamrotor;
using namespace beamrotor::test;

namespace {

/// The shipped forme-shaft rotor with its campbell analysis' `order:` set to `orders` (YAML).
std::string formeRotorWithOrders(const std::string& orders) {
  std::string text = fileContents(problemsDir() / "forme_shaft_rotor.yaml");
  const std::string campbell = "steps: 40}";
  const std::size_t at = text.find("{type: campbell");
  REQUIRE(at != std::string::npos);
  const std::size_t end = text.find(campbell, at);
  REQUIRE(end != std::string::npos);
  text.replace(end, campbell.size(), "steps: 40, order: " + orders + "}");
  return text;
}

}  // namespace

TEST_SUITE("rotor decks") {
  TEST_CASE("campbell: further excitation orders meet a constant bounce line at bounce / n") {
    StudyRequest request;
    request.deckPath = "forme_shaft_rotor_orders.yaml";
    request.sets = {"E=2e17"};
    const Study study = solveStudyText(formeRotorWithOrders("[1, 0.5, 2]"), request);
    REQUIRE(study.run);
    const double bounceRpm = deckValue(study.deck, "bounce") * 60 / (2 * std::acos(-1.0));
    const CampbellOutcome* campbell = nullptr;
    for (const AnalysisOutcome& a : study.run->analyses)
      if (a.type == "campbell") campbell = resultOf<CampbellOutcome>(a);
    REQUIRE(campbell != nullptr);
    // Order 1 stays the critical speeds' order: the two bounce lines (y and z) first.
    REQUIRE(campbell->criticalSpeeds.size() >= 2);
    CHECK(campbell->order == 1);
    CHECK(std::abs(campbell->criticalSpeeds[0].rpm / bounceRpm - 1) < 1e-6);
    CHECK(campbell->furtherOrders == std::vector<double>{0.5, 2});
    // Each further order crosses both bounce lines at bounce / n (2 x bounce is inside the
    // 0-20000 rpm sweep for 0.5: the bounce critical lies near 9740 rpm).
    REQUIRE(bounceRpm * 2 < 20000);
    for (double order : {0.5, 2.0}) {
      CAPTURE(order);
      int met = 0;
      for (const CriticalSpeed& k : campbell->furtherCriticalSpeeds)
        if (k.order == order && std::abs(k.rpm / (bounceRpm / order) - 1) < 1e-6) ++met;
      CHECK(met == 2);
      for (const CriticalSpeed& k : campbell->furtherCriticalSpeeds)
        CHECK(std::abs(k.frequencyHz - k.order * k.rpm / 60) < 1e-9 * k.frequencyHz);
    }
  }

  TEST_CASE("campbell: an order listed twice is refused at its place") {
    const DeckError e = readingError(formeRotorWithOrders("[1, 2, 2]"), "orders_twice.yaml");
    CHECK(std::string(e.what()).find("orders_twice.yaml") != std::string::npos);
    CHECK(std::string(e.what()).find("listed twice") != std::string::npos);
    CHECK(std::string(e.what()).find("order[2]") != std::string::npos);
  }
}
