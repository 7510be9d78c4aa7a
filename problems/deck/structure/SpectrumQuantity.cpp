#include "problems/deck/structure/SpectrumQuantity.hpp"

#include <algorithm>

#include "problems/deck/Deck.hpp"
#include "problems/deck/ReaderContext.hpp"
#include "problems/deck/parse/Field.hpp"
#include "problems/deck/parse/Suggest.hpp"

namespace beamrotor {

/// "3" -> 3 (Quantity.cpp, which every family's quantities share).
int parseOrdinal(const std::string& word, const std::string& what);

namespace {

/// x, y or z as the translation along it.
Dof parseDirection(const std::string& word) {
  if (word == "x") return Dof::ux;
  if (word == "y") return Dof::uy;
  if (word == "z") return Dof::uz;
  throw std::invalid_argument("'" + word + "' is not a direction (x, y or z)");
}

}  // namespace

bool parseSpectrumQuantity(const std::vector<std::string>& words, Quantity& q) {
  const std::string& head = words[0];
  if (head == "effective_mass") {
    if (words.size() != 3)
      throw std::invalid_argument("expected 'effective_mass N DIR', e.g. 'effective_mass 1 x'");
    q.kind = Quantity::Kind::effectiveMass;
    q.mode = parseOrdinal(words[1], "mode number");
    q.dof = parseDirection(words[2]);
    return true;
  }
  if (head == "captured_mass") {
    if (words.size() != 2)
      throw std::invalid_argument("expected 'captured_mass DIR', e.g. 'captured_mass x'");
    q.kind = Quantity::Kind::effectiveMass;
    q.mode = 0;
    q.dof = parseDirection(words[1]);
    return true;
  }
  if (head == "base_motion") {
    const std::string what = words.size() > 1 ? words[1] : "";
    q.kind = Quantity::Kind::baseMotion;
    q.property = what;
    if ((what == "transmissibility" || what == "relative" || what == "absolute") &&
        words.size() == 4 && words[3] == "max") {
      q.target = words[2];
      return true;
    }
    if (what == "base_force" && words.size() == 3 && words[2] == "max") return true;
    if (what == "peak_frequency" && words.size() == 3) {
      q.target = words[2];
      return true;
    }
    throw std::invalid_argument(
        "expected 'base_motion transmissibility|relative|absolute POINT max', "
        "'base_motion base_force max' or 'base_motion peak_frequency POINT'");
  }
  if (head != "spectrum") return false;
  q.kind = Quantity::Kind::spectrum;
  const std::string what = words.size() > 1 ? words[1] : "";
  q.property = what;
  if ((what == "displacement" || what == "reaction") && words.size() == 4) {
    q.target = words[2];
    q.dof = parseComponent(words[3]);
    return true;
  }
  if (what == "base_shear" && words.size() == 3) {
    q.dof = parseDirection(words[2]);
    return true;
  }
  if (what == "member" && words.size() == 5) {
    q.target = words[2];
    const std::vector<std::string> components{"N", "Vy", "Vz", "T", "My", "Mz"};
    if (std::find(components.begin(), components.end(), words[3]) == components.end())
      throw std::invalid_argument("'" + words[3] + "' is not a resultant (N Vy Vz T My Mz)");
    if (words[4] != "max")
      throw std::invalid_argument("a response-spectrum peak is a magnitude: 'max', not '" +
                                  words[4] + "'");
    q.extreme = words[3];
    return true;
  }
  throw std::invalid_argument(
      "expected 'spectrum displacement POINT DOF', 'spectrum reaction SUPPORT DOF', "
      "'spectrum base_shear x|y|z' or 'spectrum member NAME N|Vy|Vz|T|My|Mz max'");
}

void requireSpectrumNames(const Deck& deck, const Quantity& q, const Field& f) {
  if (q.kind != Quantity::Kind::spectrum && q.kind != Quantity::Kind::baseMotion) return;
  std::vector<std::string> names;
  std::string what;
  if (q.property == "base_force" || q.property == "base_shear") return;  // no name
  if (q.property == "reaction") {
    Quantity plain = q;
    plain.kind = Quantity::Kind::reaction;
    return reader::requireReactionTarget(deck, plain, f);
  }
  if (q.property == "member") {
    if (!deck.frame)
      f.fail("member quantities need a frame (nodes: and members:); this deck is a line");
    for (const DeckSegment& s : deck.segments) names.push_back(s.name);
    what = "member";
  } else {
    for (const DeckPoint& p : deck.points) names.push_back(p.name);
    what = "point";
  }
  if (std::find(names.begin(), names.end(), q.target) == names.end())
    f.fail("no " + what + " named '" + q.target + "'" + didYouMean(q.target, names) + " (" +
           joinNames(names) + ")");
}

}  // namespace beamrotor
