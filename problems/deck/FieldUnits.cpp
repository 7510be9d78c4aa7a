#include "problems/deck/FieldUnits.hpp"

#include <cctype>
#include <numbers>
#include <unordered_map>

#include "problems/deck/crank/CrankQuantity.hpp"

namespace beamrotor {

namespace {

constexpr double kRpm = 2 * std::numbers::pi / 60;

using Table = std::unordered_map<std::string, FieldUnit>;

void add(Table& t, const std::string& prefix, std::initializer_list<const char*> keys,
         const Dimension& d, double bareSize = 1) {
  for (const char* k : keys) t[prefix + k] = FieldUnit{d, bareSize};
}

const Table& table() {
  static const Table t = [] {
    Table t;
    add(t, "materials[].", {"E", "G"}, dim::pressure);
    add(t, "materials[].", {"rho"}, dim::density);
    add(t, "sections[].", {"D", "t", "b", "h", "depth"}, dim::length);
    add(t, "sections[].", {"A"}, dim::area);
    add(t, "sections[].", {"I", "Iy", "Iz", "J"}, dim::secondMoment);
    add(t, "segments[].", {"length", "size"}, dim::length);
    add(t, "segments[].", {"axial_force"}, dim::force);
    add(t, "points[].", {"at"}, dim::length);
    add(t, "supports[].prescribe.", {"ux", "uy", "uz"}, dim::length);
    add(t, "supports[].prescribe.", {"rx", "ry", "rz"}, dim::angle);
    add(t, "masses[].", {"m"}, dim::mass);
    add(t, "masses[].", {"Jp", "Jd"}, dim::inertia);
    add(t, "masses[].disk.", {"D", "bore", "width"}, dim::length);
    add(t, "masses[].disk.", {"rho"}, dim::density);
    add(t, "loads[].", {"fx", "fy", "fz"}, dim::force);
    add(t, "loads[].", {"mx", "my", "mz"}, dim::moment);
    add(t, "loads[].", {"qx", "qy", "qz"}, dim::forcePerLength);
    add(t, "loads[].", {"g"}, dim::acceleration);
    add(t, "load_cases[].loads[].", {"fx", "fy", "fz"}, dim::force);
    add(t, "load_cases[].loads[].", {"mx", "my", "mz"}, dim::moment);
    add(t, "load_cases[].loads[].", {"qx", "qy", "qz"}, dim::forcePerLength);
    add(t, "load_cases[].loads[].", {"g"}, dim::acceleration);
    for (const char* prefix : {"loads[].", "load_cases[].loads[]."}) {
      add(t, prefix, {"qx[]", "qy[]", "qz[]"}, dim::forcePerLength);  // [start, end]
      add(t, prefix, {"from_length", "to_length"}, dim::length);
    }
    add(t, "analyses[].", {"dt", "end", "period"}, dim::time);
    add(t, "analyses[].rayleigh.", {"alpha"}, dim::frequency);
    add(t, "analyses[].rayleigh.", {"beta"}, dim::time);
    add(t, "analyses[].loads[].", {"period"}, dim::time);
    add(t, "analyses[].loads[].pieces[].", {"from"}, dim::time);
    add(t, "analyses[].loads[].harmonics.", {"omega"}, dim::angularSpeed);
    add(t, "analyses[].loads[].harmonics.terms[].", {"phase"}, dim::angle);
    add(t, "analyses[].", {"speed_rpm", "from_rpm", "to_rpm"}, dim::angularSpeed, kRpm);
    add(t, "analyses[].unbalance[].", {"me"}, dim::massLength);
    add(t, "analyses[].", {"from_hz", "to_hz"}, dim::frequency);
    add(t, "analyses[].", {"from_k", "to_k"}, dim::stiffness);
    add(t, "analyses[].", {"g"}, dim::acceleration);
    add(t, "analyses[].operating.", {"min_rpm", "max_rpm"}, dim::angularSpeed, kRpm);
    add(t, "analyses[].unbalance[].", {"phase"}, dim::angle);
    for (const char* prefix : {"bearings[].", "bearings[].table[]."}) {
      add(t, prefix, {"kxx", "kyy", "kxy", "kyx"}, dim::stiffness);
      add(t, prefix, {"cxx", "cyy", "cxy", "cyx"}, dim::damping);
    }
    add(t, "bearings[].table[].", {"speed_rpm"}, dim::angularSpeed, kRpm);
    add(t, "bearings[].", {"D", "L", "c"}, dim::length);
    add(t, "bearings[].", {"mu"}, Dimension::of(-1, 1, -1, 0));  // dynamic viscosity, Pa s
    add(t, "bearings[].", {"load"}, dim::force);
    add(t, "bearings[].", {"from_rpm", "to_rpm"}, dim::angularSpeed, kRpm);
    add(t, "analyses[].", {"r", "l", "plunger_diameter"}, dim::length);
    add(t, "analyses[].masses.", {"eccentric", "slider", "rod"}, dim::mass);
    add(t, "analyses[].masses.", {"eccentricity", "rod_com_to_crank_pin", "rod_com_to_slider_pin"},
        dim::length);
    add(t, "analyses[].masses.", {"rod_residual_inertia"}, dim::inertia);
    add(t, "analyses[].body.", {"weight"}, dim::force);
    add(t, "analyses[].body.", {"mass"}, dim::mass);
    add(t, "analyses[].body.", {"radius_of_gyration", "l1", "l2"}, dim::length);
    add(t, "analyses[].body.", {"C1", "C2"}, dim::stiffness);
    add(t, "damping.", {"alpha"}, dim::frequency);
    add(t, "damping.", {"beta"}, dim::time);
    return t;
  }();
  return t;
}

/// "segments[2].length" -> "segments[].length".
std::string withoutIndices(const std::string& path) {
  std::string out;
  for (std::size_t i = 0; i < path.size(); ++i) {
    out += path[i];
    if (path[i] != '[') continue;
    std::size_t j = i + 1;
    while (j < path.size() && std::isdigit(static_cast<unsigned char>(path[j]))) ++j;
    i = j - 1;
  }
  return out;
}

}  // namespace

FieldUnit fieldUnitAt(const std::string& path) {
  const auto found = table().find(withoutIndices(path));
  return found == table().end() ? FieldUnit{} : found->second;
}

FieldUnit unitForDof(Dof d, const Dimension& translational, const Dimension& rotational) {
  return FieldUnit{isRotation(d) ? rotational : translational};
}

FieldUnit referenceUnit(const beamrotor::Quantity& q) {
  using K = beamrotor::Quantity::Kind;
  switch (q.kind) {
    case K::reaction:
      return unitForDof(q.dof, dim::force, dim::moment);
    case K::displacement:
      return unitForDof(q.dof, dim::length, dim::angle);
    case K::frequency:
      return {dim::frequency};
    case K::maxStress:
    case K::maxShear:
      return {dim::pressure};
    case K::maxMoment:
      return {dim::moment};
    case K::criticalSpeed:
      return {dim::angularSpeed, kRpm};
    case K::unbalanceAmplitude:
      return {dim::length};
    case K::rigidBody: {
      const std::string& p = q.property;
      if (p == "mass") return {dim::mass};
      if (p == "com_x") return {dim::length};
      if (p == "J_com" || p == "Jp") return {dim::inertia};
      if (p == "f1" || p == "f2" || p == "paper_f1" || p == "paper_f2") return {dim::frequency};
      if (p == "n1" || p == "n2" || p == "paper_n1" || p == "paper_n2")
        return {dim::lengthPerAngle};
      return {dim::force};  // FA1, FB1, FA2, FB2
    }
    case K::crankSlider:
      return crankReferenceUnit(q);
    default:
      return {};  // log_decrement; histories: their unit is free text
  }
}

}  // namespace beamrotor
