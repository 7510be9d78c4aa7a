// The check quantities of the rotor analyses (grammar in Quantity.hpp), as read from a deck;
// problems/run/MeasureRotor.hpp measures them.
#pragma once

#include <string>
#include <vector>

#include "problems/deck/Quantity.hpp"

namespace beamrotor {

/// "3" -> 3 for a 1-based number; throws std::invalid_argument naming `what` otherwise.
int parseOrdinal(const std::string& word, const std::string& what);

/// The rigid_body properties a check may name.
const std::vector<std::string>& rigidBodyPropertyNames();
/// The properties `level1 PROPERTY` names: qa, q0 (N/m), q0_over_qa, log_decrement_at_qa.
const std::vector<std::string>& levelOnePropertyNames();
/// The properties `pad_mode N PROPERTY` reads of a pad's own mode.
const std::vector<std::string>& padModePropertyNames();

/// Fills q when `words` is a rotor quantity and returns true; false when the first word is
/// not one; throws std::invalid_argument when it is one, written wrongly.
bool parseRotorQuantity(const std::vector<std::string>& words, Quantity& q);

}  // namespace beamrotor
