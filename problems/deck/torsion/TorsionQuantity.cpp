#include "problems/deck/torsion/TorsionQuantity.hpp"

#include <stdexcept>

namespace beamrotor {

bool parseTorsionQuantity(const std::vector<std::string>& words, Quantity& q) {
  if (words[0] != "torsion") return false;
  if (words.size() != 3 || (words[1] != "torque" && words[1] != "twist"))
    throw std::invalid_argument("expected 'torsion torque NAME' or 'torsion twist STATION'");
  q.kind = Quantity::Kind::torsion;
  q.property = words[1];
  q.target = words[2];
  return true;
}

}  // namespace beamrotor
