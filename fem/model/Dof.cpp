#include "fem/model/Dof.hpp"

namespace beamrotor {

namespace {
constexpr std::array<std::string_view, kDofKinds> kNames{"ux", "uy", "uz", "rx", "ry", "rz"};
}

std::string_view dofName(Dof d) {
  return kNames[dofIndex(d)];
}

std::optional<Dof> parseDof(std::string_view name) {
  for (Dof d : kAllDofs)
    if (kNames[dofIndex(d)] == name) return d;
  return std::nullopt;
}

std::string toString(const NodeDof& d) {
  return "node " + std::to_string(d.node) + " " + std::string(dofName(d.dof));
}

}  // namespace beamrotor
