// Expressions in decks (muparser): arithmetic, parameters referring to earlier ones, and the
// ways an expression can fail.
#include <doctest/doctest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

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

  TEST_CASE("a plain literal is read as the full evaluation reads it, bit for bit") {
    // Literals skip muparser (most numbers of a generated deck); in parentheses they take the
    // full path (every scaling, then the dimension): both must give the same amount.
    ExpressionEvaluator e;
    std::vector<std::string> texts{"0", "-0", "0.0", "5000", "-5000", "0.3", "3.5", "1.",
                                   "007", "2.1e11", "210000000000.0", "1e-3", "1E+3",
                                   "-4.9406564584124654e-324", "1.7976931348623157e308"};
    // Random doubles written to 17 significant digits (where round-trip reading is exact).
    std::uint64_t state = 0x9E3779B97F4A7C15ULL;
    for (int k = 0; k < 200; ++k) {
      state = state * 6364136223846793005ULL + 1442695040888963407ULL;
      const double x = std::ldexp(double(state >> 11), int(state % 80) - 93);
      char text[40];
      std::snprintf(text, sizeof text, k % 2 ? "%.17g" : "-%.16e", x);
      texts.push_back(text);
    }
    for (const std::string& text : texts) {
      CAPTURE(text);
      const Amount fast = e.amount(text), full = e.amount("(" + text + ")");
      CHECK(std::bit_cast<std::uint64_t>(fast.si) == std::bit_cast<std::uint64_t>(full.si));
      CHECK(fast.anyDimension == full.anyDimension);
      CHECK(fast.dimension.exponents == full.dimension.exponents);
    }
    // Not literals: evaluated in full, with their errors.
    CHECK(e.evaluate("+5") == 5);
    CHECK(e.evaluate("1e2 * 2") == 200);
    CHECK_THROWS_AS(e.evaluate("1e400"), ExpressionError);
    CHECK_THROWS_AS(e.evaluate("1e"), ExpressionError);
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
