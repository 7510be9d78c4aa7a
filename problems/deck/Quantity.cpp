#include "problems/deck/Quantity.hpp"

#include <algorithm>
#include <iterator>
#include <sstream>
#include <vector>

#include "problems/deck/crank/CrankQuantity.hpp"
#include "problems/deck/parse/PlainText.hpp"
#include "problems/deck/rotor/RotorQuantity.hpp"
#include "problems/deck/structure/SpectrumQuantity.hpp"
#include "problems/deck/torsion/TorsionQuantity.hpp"

namespace beamrotor {

namespace {

constexpr const char* kGrammar =
    "expected 'reaction SUPPORT DOF', 'displacement POINT DOF', "
    "'displacement POINT ROTATION left|right', 'frequency N', 'stress max', "
    "'shear max', 'moment max', 'displacement max', 'member NAME N|Vy|Vz|T|My|Mz max|min|maxabs', "
    "'member NAME deflection max', 'section NAME PROPERTY', 'buckling_factor N', 'log_decrement N', 'critical_speed N', "
    "'instability_onset', "
    "'unbalance_amplitude POINT at RPM', "
    "'rigid_body PROPERTY', 'level1 PROPERTY', 'runup peak|speed_at_peak POINT', "
    "'runup eccentricity BEARING', 'runup end_speed', 'runup film_torque', "
    "'runup rub_force|rub_torque|rub_time RUB', "
    "'crank PROPERTY', 'crank PROPERTY at LAMBDA', "
    "'crank PROPERTY at PHI deg', 'torsion torque NAME', 'torsion twist STATION', "
    "'history NAME max|min|maxabs', 'history NAME at TIME', 'resultant N|Vy|Vz|T|My|Mz at POINT', "
    "'moving max|min QUANTITY', "
    "'spectrum displacement|reaction NAME DOF', 'spectrum base_shear DIR', "
    "'spectrum member NAME COMP max', 'effective_mass N DIR', 'captured_mass DIR', "
    "'base_motion transmissibility|relative|absolute POINT max', 'base_motion base_force max' "
    "or 'base_motion peak_frequency POINT'";

}  // namespace

Dof parseComponent(const std::string& word) {
  if (auto d = parseDof(word)) return *d;
  static const std::vector<std::pair<std::string, Dof>> aliases{{"fx", Dof::ux}, {"fy", Dof::uy},
                                                                {"fz", Dof::uz}, {"mx", Dof::rx},
                                                                {"my", Dof::ry}, {"mz", Dof::rz}};
  for (const auto& [name, dof] : aliases)
    if (word == name) return dof;
  throw std::invalid_argument("'" + word +
                              "' is not a component (ux uy uz rx ry rz, or fx fy fz mx my mz)");
}

int parseOrdinal(const std::string& n, const std::string& what) {
  const bool digits = !n.empty() && n.size() <= 4 &&
                      std::all_of(n.begin(), n.end(), [](char c) { return c >= '0' && c <= '9'; });
  if (!digits || std::stoi(n) < 1)
    throw std::invalid_argument(what + " '" + n + "' must be a whole number from 1");
  return std::stoi(n);
}

Quantity parseQuantity(const std::string& text) {
  // One line of words: the text is shown in tables and chart captions as it is.
  if (const auto bad = firstNonPlain(text, " "))
    throw std::invalid_argument("a quantity is one line of words; it holds " +
                                describeNonPlain(text, *bad));
  std::istringstream in(text);
  std::vector<std::string> words;
  for (std::string w; in >> w;) words.push_back(w);
  Quantity q;
  q.text = text;
  if (words.empty()) throw std::invalid_argument(std::string("empty quantity; ") + kGrammar);
  const std::string& head = words[0];
  if ((head == "reaction" || head == "displacement") && words.size() == 3) {
    q.kind = head == "reaction" ? Quantity::Kind::reaction : Quantity::Kind::displacement;
    q.target = words[1];
    q.dof = parseComponent(words[2]);
    return q;
  }
  if (head == "displacement" && words.size() == 4) {
    q.kind = Quantity::Kind::displacement;
    q.target = words[1];
    q.dof = parseComponent(words[2]);
    if (words[3] != "left" && words[3] != "right")
      throw std::invalid_argument("'" + words[3] + "' is not a side (left or right)");
    if (!isRotation(q.dof))
      throw std::invalid_argument("a side names one of the two rotations at a hinge; " + words[2] +
                                  " is a translation, the same on both sides");
    q.side = words[3] == "left" ? Quantity::Side::left : Quantity::Side::right;
    return q;
  }
  if (head == "displacement" && words.size() == 2 && words[1] == "max") {
    q.kind = Quantity::Kind::maxDisplacement;
    return q;
  }
  if (head == "member" && words.size() == 4) {
    q.target = words[1];
    if (words[2] == "deflection") {
      if (words[3] != "max")
        throw std::invalid_argument("a member's deflection from its chord has 'max' only, not '" +
                                    words[3] + "'");
      q.kind = Quantity::Kind::memberDeflection;
      return q;
    }
    const std::vector<std::string> components{"N", "Vy", "Vz", "T", "My", "Mz"};
    if (std::find(components.begin(), components.end(), words[2]) == components.end())
      throw std::invalid_argument("'" + words[2] +
                                  "' is not a member quantity (N Vy Vz T My Mz, or deflection)");
    if (words[3] != "max" && words[3] != "min" && words[3] != "maxabs")
      throw std::invalid_argument("'" + words[3] + "' is not an extreme (max, min or maxabs)");
    q.kind = Quantity::Kind::memberForce;
    q.property = words[2];
    q.extreme = words[3];
    return q;
  }
  if (head == "resultant" && words.size() == 4 && words[2] == "at") {
    const std::vector<std::string> components{"N", "Vy", "Vz", "T", "My", "Mz"};
    if (std::find(components.begin(), components.end(), words[1]) == components.end())
      throw std::invalid_argument("'" + words[1] + "' is not a resultant (N Vy Vz T My Mz)");
    q.kind = Quantity::Kind::resultantAt;
    q.property = words[1];
    q.target = words[3];
    return q;
  }
  if (head == "moving" && words.size() >= 3) {
    if (words[1] != "max" && words[1] != "min")
      throw std::invalid_argument("'" + words[1] + "' is not an extreme of a moving load (max or min)");
    q.kind = words[1] == "max" ? Quantity::Kind::movingMax : Quantity::Kind::movingMin;
    std::string rest = words[2];
    for (std::size_t w = 3; w < words.size(); ++w) rest += " " + words[w];
    auto inner = std::make_shared<Quantity>(parseQuantity(rest));
    if (inner->kind != Quantity::Kind::reaction && inner->kind != Quantity::Kind::resultantAt &&
        !(inner->kind == Quantity::Kind::displacement && inner->side == Quantity::Side::node))
      throw std::invalid_argument("a moving load's envelope is of a reaction, a displacement or a "
                                  "resultant at a point, not '" + rest + "'");
    q.inner = std::move(inner);
    return q;
  }
  if (head == "section" && words.size() == 3) {
    q.kind = Quantity::Kind::sectionProperty;
    q.target = words[1];
    q.property = words[2];
    if (std::none_of(std::begin(kSectionProperties), std::end(kSectionProperties),
                     [&](const char* p) { return q.property == p; }))
      throw std::invalid_argument("'" + q.property +
                                  "' is not a section property (A Iy Iz It Wel_y Wel_z Wpl_y "
                                  "Wpl_z; y-y the strong axis)");
    return q;
  }
  if (head == "frequency" && words.size() == 2) {
    q.kind = Quantity::Kind::frequency;
    q.mode = parseOrdinal(words[1], "mode number");
    return q;
  }
  if (head == "buckling_factor" && words.size() == 2) {
    q.kind = Quantity::Kind::bucklingFactor;
    q.mode = parseOrdinal(words[1], "mode number");
    return q;
  }
  if (parseRotorQuantity(words, q)) return q;
  if (parseCrankQuantity(words, q)) return q;
  if (parseTorsionQuantity(words, q)) return q;
  if (parseSpectrumQuantity(words, q)) return q;
  if ((head == "stress" || head == "shear" || head == "moment") && words.size() == 2 &&
      words[1] == "max") {
    q.kind = head == "stress"  ? Quantity::Kind::maxStress
             : head == "shear" ? Quantity::Kind::maxShear
                               : Quantity::Kind::maxMoment;
    return q;
  }
  if (head == "history" && words.size() == 3 &&
      (words[2] == "max" || words[2] == "min" || words[2] == "maxabs")) {
    q.kind = words[2] == "max"   ? Quantity::Kind::historyMax
             : words[2] == "min" ? Quantity::Kind::historyMin
                                 : Quantity::Kind::historyMaxAbs;
    q.target = words[1];
    return q;
  }
  if (head == "history" && words.size() == 4 && words[2] == "at") {
    q.kind = Quantity::Kind::historyAt;
    q.target = words[1];
    q.timeText = words[3];
    return q;
  }
  throw std::invalid_argument("cannot read '" + text + "'; " + kGrammar);
}

}  // namespace beamrotor
