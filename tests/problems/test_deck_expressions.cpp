// Expressions in decks (muparser): arithmetic, parameters referring to earlier ones, and the
// ways an expression can fail.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

#include "problems/deck/parse/Expression.hpp"
#include "problems/deck/parse/Suggest.hpp"

using namespace beamrotor;

namespace {

std::string failureOf(const ExpressionEvaluator& ev, const std::string& text) {
  try {
    ev.evaluate(text);
  } catch (const ExpressionError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_SUITE("deck expressions") {
  TEST_CASE("numbers, operators, functions and pi") {
    ExpressionEvaluator ev;
    CHECK(ev.evaluate("200e9") == 200e9);
    CHECK(ev.evaluate("0.715 - 0.4") == doctest::Approx(0.315).epsilon(1e-15));
    CHECK(ev.evaluate("2^10") == 1024);
    CHECK(ev.evaluate("-2^2") == -4);  // unary minus binds looser than ^
    CHECK(ev.evaluate("sqrt(16) + abs(-3) + max(1, 7)") == 14);
    CHECK(ev.evaluate("pi") == std::numbers::pi);
    CHECK(ev.evaluate("1 < 2 && 3 == 3") == 1);
    CHECK(ev.evaluate("0.4 == 0.4") == 1);
    CHECK(ev.evaluate("1 > 2 ? 5 : 6") == 6);
  }

  TEST_CASE("names defined in order, each usable by the next") {
    ExpressionEvaluator ev;
    ev.define("a", 0.575);
    ev.define("eta", 0.4);
    ev.define("at", ev.evaluate("a + 0.715 - eta"));
    CHECK(ev.evaluate("at") == doctest::Approx(0.89).epsilon(1e-15));
    CHECK(ev.names() == std::vector<std::string>{"a", "eta", "at"});
    CHECK_THROWS_AS(ev.define("eta", 1), ExpressionError);   // twice
    CHECK_THROWS_AS(ev.define("sin", 1), ExpressionError);   // a function
    CHECK_THROWS_AS(ev.define("pi", 3), ExpressionError);    // the constant
    CHECK_THROWS_AS(ev.define("2x", 1), ExpressionError);    // not an identifier
    CHECK_THROWS_AS(ev.define("x", NAN), ExpressionError);
  }

  TEST_CASE("failures say why") {
    ExpressionEvaluator ev;
    ev.define("eta", 0.4);
    CHECK(failureOf(ev, "1/(eta - eta)").find("evaluates to inf") != std::string::npos);
    CHECK(failureOf(ev, "sqrt(-1)").find("evaluates to nan") != std::string::npos);
    CHECK(failureOf(ev, "eta + etb").find("unknown name 'etb'; did you mean 'eta'?") !=
          std::string::npos);
    CHECK(failureOf(ev, "1 +* 2").find("cannot evaluate") != std::string::npos);
    CHECK(failureOf(ev, "1, 2").find("2 comma-separated values") != std::string::npos);
    CHECK(failureOf(ev, "").find("empty") != std::string::npos);
    // An assignment would change a parameter behind the deck's back: not allowed.
    CHECK(failureOf(ev, "eta = 3") != "");
    CHECK(ev.evaluate("eta") == 0.4);
    CHECK(failureOf(ev, std::string(5000, '1')).find("longer than") != std::string::npos);
  }

  TEST_CASE("did-you-mean by edit distance") {
    CHECK(editDistance("lenght", "length") == 2);
    CHECK(editDistance("", "abc") == 3);
    CHECK(editDistance("segmnts", "segments") == 1);
    const std::vector<std::string> keys{"name", "length", "section", "elements", "size"};
    CHECK(closestMatch("lenght", keys) == "length");
    CHECK(closestMatch("elemnts", keys) == "elements");
    CHECK(closestMatch("Size", keys) == "size");
    CHECK(closestMatch("colour", keys).empty());  // nothing plausible: no suggestion
  }
}
