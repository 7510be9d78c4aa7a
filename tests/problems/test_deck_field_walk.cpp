// The field walk (issue 40): every numeric field the reader reads, in every shipped deck and
// in the fixture decks of tests/problems/field_walk, written once with a unit of its own
// dimension (the deck must read to the same numbers) and once with a unit of another (refused
// naming the field). The fields come from the reader itself (NumericReadLog), and every key
// the reader allows must be read in some deck, so a new field cannot escape the walk.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>
#include <cstdio>
#include <filesystem>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "problems/deck/DeckReader.hpp"
#include "problems/deck/parse/DeckSource.hpp"
#include "problems/deck/parse/NumericReads.hpp"
#include "problems/deck/study/DesignStudy.hpp"
#include "problems/deck/study/ReadSweepRefinement.hpp"
#include "tests/problems/DeckTestSupport.hpp"

using namespace beamrotor;

namespace {

struct Walked {
  std::vector<NumericRead> reads;
  std::vector<std::string> texts;
  std::vector<AllowedKeys> allowed;
};

/// Reads a deck (and its study: block, when it has one) with a log open.
Walked readLogged(const std::string& text, const std::string& path) {
  const NumericReadLog log;
  const DeckSource source = parseDeckText(text, path);
  const Deck deck = readDeck(source, {});
  if (text.find("\nstudy:") != std::string::npos) readDesignStudy(source, deck, {});
  readSweepRefinement(source, deck);
  return {log.reads(), log.textReads(), log.allowed()};
}

std::vector<std::filesystem::path> walkedDecks() {
  std::vector<std::filesystem::path> decks = test::shippedDecks();
  const auto dir = std::filesystem::path(BEAMROTOR_SOURCE_DIR) / "tests/problems/field_walk";
  for (const auto& e : std::filesystem::directory_iterator(dir))
    if (e.path().extension() == ".yaml") decks.push_back(e.path());
  return decks;
}

std::string number(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

/// A value written with a unit of the field's dimension, and whether its SI value is the
/// field's exactly.
struct WithUnit {
  std::string text;
  bool exact = true;
};

/// The value with a unit of the field's dimension whose SI value is the field's: its bare unit
/// by name (rpm, deg), else the product of the base units (m, kg, s, rad: exact), else, where
/// the deck hides a base unit with a name of its own (a parameter `m`), mm, g, ms or deg;
/// units that cancel for a plain number.
WithUnit withOwnUnit(const NumericRead& r, const std::set<std::string>& hidden) {
  if (r.unit.bareSize != 1)
    for (const Unit& u : units())
      if (u.si == r.unit.bareSize && u.dimension == r.unit.dimension && !hidden.count(u.name))
        return {"(" + number(r.value) + ") " + u.name, false};
  const double si = r.value * r.unit.bareSize;
  struct Base {
    const char* name;
    const char* other;
    double otherSize;
  };
  const Base bases[] = {{"m", "mm", 1e-3}, {"kg", "g", 1e-3}, {"s", "ms", 1e-3},
                        {"rad", "deg", std::numbers::pi / 180}, {"K", "K", 1}};
  double scale = 1;
  std::string unit;
  for (int i = 0; i < Dimension::kBases; ++i) {
    const double e = r.unit.dimension.exponents[i];
    const bool own = !hidden.count(bases[i].name);
    const std::string name = own ? bases[i].name : bases[i].other;
    if (r.unit.dimension.dimensionless() && unit.empty() && own)
      unit = "*" + name + "/" + name;  // units that cancel
    if (e == 0) continue;
    unit += (e > 0 ? "*" : "/") + name + "^" + number(std::abs(e));
    if (!own) scale *= std::pow(bases[i].otherSize, e);
  }
  return {"(" + number(si / scale) + ")" + unit, scale == 1 && r.unit.bareSize == 1};
}
/// One of another dimension, in a unit the deck does not hide.
std::string withOtherUnit(const NumericRead& r, const std::set<std::string>& hidden) {
  for (const char* name : {"kg", "s", "rad", "m"})
    if (findUnit(name)->dimension != r.unit.dimension && !hidden.count(name))
      return std::string("1 ") + name;
  FAIL("the deck hides every base unit");
  return "";
}

/// The deck text with the value `r` read replaced by `value`; "" when the value is not
/// written where its mark says.
std::string rewritten(const std::string& text, const NumericRead& r, const std::string& value) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  if (r.place.line < 1 || r.place.line > int(lines.size())) return "";
  std::string& line = lines[r.place.line - 1];
  const std::size_t at = std::size_t(r.place.column - 1);
  std::size_t length = 0;
  if (line.compare(at, r.text.size(), r.text) == 0)
    length = r.text.size();
  else if (at < line.size() && (line[at] == '\'' || line[at] == '"') &&
           line.compare(at + 1, r.text.size(), r.text) == 0)
    length = r.text.size() + 2;
  else
    return "";
  line.replace(at, length, value);
  std::string out;
  for (const std::string& l : lines) out += l + "\n";
  return out;
}

/// "sections[2].tw" -> "sections[].tw", "study.parameters.eta.from" -> "study.parameters.*.from"
/// (a study's parameters are maps keyed by the deck's names).
std::string withoutIndices(const std::string& path) {
  const std::string study = "study.parameters.";
  if (path.compare(0, study.size(), study) == 0 && path.size() > study.size()) {
    const std::size_t end = path.find('.', study.size());
    return study + "*" + (end == std::string::npos ? "" : path.substr(end));
  }
  std::string out;
  for (std::size_t i = 0; i < path.size(); ++i) {
    out += path[i];
    if (path[i] == '[') {
      while (i + 1 < path.size() && path[i + 1] != ']') ++i;
    }
  }
  return out;
}

bool visits(const std::string& read, const std::string& key) {
  return read.compare(0, key.size(), key) == 0 &&
         (read.size() == key.size() || read[key.size()] == '.' || read[key.size()] == '[');
}

}  // namespace

TEST_SUITE("deck units") {
  TEST_CASE("every numeric field takes its unit and refuses another (the field walk)") {
    std::set<std::string> visited;  // paths without indices
    std::vector<std::pair<std::string, std::string>> allowed;  // map path, key (no indices)
    int fields = 0;
    for (const auto& path : walkedDecks()) {
      const std::string text = test::fileContents(path);
      const std::string name = path.filename().string();
      const Walked original = readLogged(text, name);
      std::set<std::string> hidden;  // the deck's own names, which hide units of that name
      {
        const Deck deck = readDeck(parseDeckText(text, name), {});
        for (const auto& named : {deck.parameters, deck.derived})
          for (const auto& [n, v] : named) hidden.insert(n);
      }
      for (const std::string& t : original.texts) visited.insert(withoutIndices(t));
      for (const AllowedKeys& a : original.allowed) {
        visited.insert(withoutIndices(a.path));
        for (const std::string& k : a.keys) allowed.emplace_back(withoutIndices(a.path), k);
      }
      std::set<std::string> done;
      for (const NumericRead& r : original.reads) {
        visited.insert(withoutIndices(r.place.field));
        if (!done.insert(r.place.field).second) continue;  // read twice: walked once
        CAPTURE(name);
        CAPTURE(r.place.field);
        CAPTURE(r.text);
        ++fields;
        const WithUnit own = withOwnUnit(r, hidden);
        const std::string right = rewritten(text, r, own.text);
        REQUIRE_MESSAGE(!right.empty(), "the value is not at line " << r.place.line
                                                                     << ", column "
                                                                     << r.place.column);
        CAPTURE(own.text);
        Walked again;
        try {
          again = readLogged(right, name);
        } catch (const DeckError& e) {
          FAIL_CHECK("refused its own unit: " << std::string(e.what()));
          continue;
        }
        // The same numbers: every field read again to its value, exactly when the unit is
        // the SI one (to round-off through rpm or mm).
        REQUIRE(again.reads.size() == original.reads.size());
        for (std::size_t k = 0; k < again.reads.size(); ++k) {
          const double was = original.reads[k].value, now = again.reads[k].value;
          if (own.exact)
            CHECK(now == was);
          else
            CHECK(now == doctest::Approx(was).epsilon(1e-14));
        }
        const std::string wrong = rewritten(text, r, withOtherUnit(r, hidden));
        try {
          readLogged(wrong, name);
          FAIL_CHECK("took " << withOtherUnit(r, hidden));
        } catch (const DeckError& e) {
          const std::string why = e.what();
          CAPTURE(why);
          CHECK(why.find(r.place.field + ":") != std::string::npos);
          CHECK(why.find("expects " + describeDimension(r.unit.dimension)) != std::string::npos);
        }
      }
    }
    MESSAGE(fields << " numeric fields walked");
    // Every key the reader allows is read in some deck.
    std::set<std::string> missing;
    for (const auto& [map, key] : allowed) {
      const std::string full = map.empty() ? key : map + "." + key;
      bool seen = false;
      for (const std::string& v : visited) seen = seen || visits(v, full);
      if (!seen) missing.insert(full);
    }
    std::string list;
    for (const std::string& m : missing) list += "\n  " + m;
    CHECK_MESSAGE(missing.empty(), "keys the reader allows that no walked deck reads (add them "
                                   "to a deck in tests/problems/field_walk):"
                                       << list);
  }
}
