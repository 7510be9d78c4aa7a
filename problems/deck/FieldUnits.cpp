#include "problems/deck/FieldUnits.hpp"

#include "problems/deck/crank/CrankQuantity.hpp"

namespace beamrotor {

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
    case K::maxDisplacement:
    case K::memberDeflection:
      return {dim::length};
    case K::movingMax:
    case K::movingMin:  // the envelope has its quantity's unit
      return referenceUnit(*q.inner);
    case K::resultantAt:
    case K::memberForce:  // N, Vy, Vz are forces; T, My, Mz moments
      return {q.property == "N" || q.property.starts_with('V') ? dim::force : dim::moment};
    case K::sectionProperty:  // A an area, I and It second moments, W moduli (m^3)
      return {q.property == "A"             ? dim::area
              : q.property.starts_with('W') ? Dimension::of(3, 0, 0, 0)
                                            : dim::secondMoment};
    case K::criticalSpeed:
    case K::instabilityOnset:
      return kRpmField;
    case K::unbalanceAmplitude:
      return {dim::length};
    case K::runUp:  // the peak amplitude (m), a journal's eccentricity ratio, or a speed (rpm)
      if (q.property == "peak") return {dim::length};
      if (q.property == "eccentricity") return {dim::none};
      if (q.property == "rub_force") return {dim::force};
      if (q.property == "rub_torque" || q.property == "film_torque") return {dim::moment};
      if (q.property == "rub_time") return {dim::time};
      return kRpmField;
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
    case K::levelOne:  // qa and q0 are cross-coupled stiffnesses; their ratio and decrement none
      return {q.property == "qa" || q.property == "q0" ? dim::stiffness : dim::none};
    case K::padMode:  // Hz; the decay rate -Re(lambda) in 1/s; the others ratios
      if (q.property == "frequency" || q.property == "decay_rate") return {dim::frequency};
      return {dim::none};
    case K::crankSlider:
      return crankReferenceUnit(q);
    case K::torsion:
      return {q.property == "torque" ? dim::moment : dim::angle};
    case K::spectrum:
      if (q.property == "member")
        return {q.extreme == "N" || q.extreme.starts_with('V') ? dim::force : dim::moment};
      if (q.property == "displacement") return unitForDof(q.dof, dim::length, dim::angle);
      return unitForDof(q.dof, dim::force, dim::moment);  // reaction, base_shear
    case K::effectiveMass:
      return {q.mode > 0 ? dim::mass : dim::none};
    case K::baseMotion:
      if (q.property == "relative" || q.property == "absolute") return {dim::length};
      if (q.property == "base_force") return {dim::force};
      if (q.property == "peak_frequency") return {dim::frequency};
      return {};  // transmissibility
    default:
      return {};  // buckling_factor, log_decrement; histories: their unit is free text
  }
}

}  // namespace beamrotor
