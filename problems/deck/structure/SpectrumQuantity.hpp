// The check quantities of the response-spectrum and base-motion analyses (grammar in problems/deck/Quantity.hpp),
// as read from a deck; problems/run/MeasureSpectrum.hpp measures them.
#pragma once

#include <string>
#include <vector>

#include "problems/deck/Quantity.hpp"

namespace beamrotor {

class Field;
struct Deck;

/// Fills q when `words` is a response-spectrum or base-motion quantity and returns true; false when the first
/// word is not one; throws std::invalid_argument when it is one, written wrongly.
bool parseSpectrumQuantity(const std::vector<std::string>& words, Quantity& q);

/// The names a response-spectrum or base-motion quantity refers to exist in `deck` (points, supports,
/// members), else `f` fails naming them.
void requireSpectrumNames(const Deck& deck, const Quantity& q, const Field& f);

}  // namespace beamrotor
