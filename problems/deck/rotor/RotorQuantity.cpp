// Check quantities of the rotor analyses, as read from a deck (see RotorQuantity.hpp).
#include "problems/deck/rotor/RotorQuantity.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace beamrotor {

const std::vector<std::string>& rigidBodyPropertyNames() {
  // paper_*: the same modes under the paper's names (its k1 is the higher frequency).
  static const std::vector<std::string> names{
      "mass", "com_x", "J_com",    "Jp",       "f1",       "f2",       "n1",      "n2",
      "FA1",  "FB1",   "FA2",      "FB2",      "paper_f1", "paper_f2", "paper_n1", "paper_n2"};
  return names;
}

const std::vector<std::string>& levelOnePropertyNames() {
  static const std::vector<std::string> names{"qa", "q0", "q0_over_qa", "log_decrement_at_qa",
                                                "critical_speed_ratio", "rigid_critical_speed"};
  return names;
}

const std::vector<std::string>& padModePropertyNames() {
  static const std::vector<std::string> names{"frequency", "decay_rate", "damping_ratio",
                                              "log_decrement", "bearing_energy"};
  return names;
}

bool parseRotorQuantity(const std::vector<std::string>& words, Quantity& q) {
  const std::string& head = words[0];
  using Kind = Quantity::Kind;
  if (head == "log_decrement" || head == "critical_speed") {
    if (words.size() != 2) throw std::invalid_argument("expected '" + head + " N'");
    q.kind = head == "log_decrement" ? Kind::logDecrement : Kind::criticalSpeed;
    q.mode =
        parseOrdinal(words[1], head == "log_decrement" ? "mode number" : "critical speed number");
    return true;
  }
  if (head == "pad_mode") {
    const auto& names = padModePropertyNames();
    if (words.size() != 3 || std::find(names.begin(), names.end(), words[2]) == names.end()) {
      std::string list;
      for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
      throw std::invalid_argument("expected 'pad_mode N PROPERTY', PROPERTY one of " + list);
    }
    q.kind = Kind::padMode;
    q.mode = parseOrdinal(words[1], "pad mode number");
    q.property = words[2];
    return true;
  }
  if (head == "instability_onset") {
    if (words.size() != 1) throw std::invalid_argument("expected 'instability_onset'");
    q.kind = Kind::instabilityOnset;
    return true;
  }
  if (head == "unbalance_amplitude") {
    if (words.size() != 4 || words[2] != "at")
      throw std::invalid_argument("expected 'unbalance_amplitude POINT at RPM'");
    q.kind = Kind::unbalanceAmplitude;
    q.target = words[1];
    std::size_t used = 0;
    try {
      q.rpm = std::stod(words[3], &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != words[3].size() || !std::isfinite(q.rpm) || q.rpm < 0)
      throw std::invalid_argument("speed '" + words[3] + "' must be a number of rpm >= 0");
    return true;
  }
  if (head == "runup") {
    const bool ofPoint =
        words.size() == 3 && (words[1] == "peak" || words[1] == "speed_at_peak" ||
                              words[1] == "eccentricity" || words[1] == "rub_force" ||
                              words[1] == "rub_torque" || words[1] == "rub_time");
    const bool ofRun = words.size() == 2 && (words[1] == "end_speed" || words[1] == "film_torque");
    if (!ofPoint && !ofRun)
      throw std::invalid_argument(
          "expected 'runup peak POINT', 'runup speed_at_peak POINT', 'runup eccentricity BEARING', "
          "'runup rub_force|rub_torque|rub_time RUB', 'runup end_speed' or 'runup film_torque'");
    q.kind = Kind::runUp;
    q.property = words[1];
    if (ofPoint) q.target = words[2];
    return true;
  }
  if (head == "rigid_body" || head == "level1") {
    const bool rigid = head == "rigid_body";
    const auto& names = rigid ? rigidBodyPropertyNames() : levelOnePropertyNames();
    if (words.size() != 2 || std::find(names.begin(), names.end(), words[1]) == names.end()) {
      std::string list;
      for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
      throw std::invalid_argument("expected '" + head + " PROPERTY', PROPERTY one of " + list);
    }
    q.kind = rigid ? Kind::rigidBody : Kind::levelOne;
    q.property = words[1];
    return true;
  }
  return false;
}

}  // namespace beamrotor
