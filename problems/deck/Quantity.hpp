// The quantities a deck's checks compare with closed forms, written as short phrases:
//   reaction SUPPORT DOF      support reaction (N, N m); DOF ux uy uz rx ry rz or fx .. mz
//   displacement POINT DOF    displacement (m) or rotation (rad) of a named point
//   displacement POINT ROT left|right   the rotation of the beam end left (ending there) or
//                             right (starting there) of the point: a hinge's two rotations
//   frequency N               natural frequency of mode N (Hz), N from 1
//   stress max                largest |normal stress| on the outer fibres of any beam (Pa)
//   shear max                 largest transverse shear stress in any beam (Pa),
//   fem/model/ShearStress moment max                largest bending moment magnitude in any beam (N
//   m) history NAME max|min|maxabs   largest, smallest or largest |value| of a transient history
//   displacement max          largest translation anywhere, inside elements too (m)
//   member NAME COMP max|min|maxabs   extreme of a resultant (N Vy Vz T My Mz) along a member
//   member NAME deflection max   largest deflection of a member from its chord (m)
//   buckling_factor N         N-th lowest positive load factor of a buckling analysis
//   section NAME PROPERTY     a cross-section's A, Iy, Iz, It, Wel_y, Wel_z, Wpl_y or Wpl_z in
//                             the steel tables' axes (y-y strong; m^2, m^4, m^3), from any
//                             analysis of the beams (MeasureSection.hpp)
//   history NAME at TIME      a transient history at TIME (s; an expression without spaces),
//                             interpolated linearly between samples
//   resultant COMP at POINT   a resultant (N Vy Vz T My Mz, local axes) at a named point: at
//                             the start of the beam that starts there, else at the end of the
//                             one that ends there
//   moving max|min QUANTITY   the largest or smallest value of a reaction, displacement or
//                             resultant while a moving-load analysis' train crosses its path
// those of the rotor analyses (RotorQuantity.cpp):
//   frequency N               in a rotor analysis: damped whirl frequency of mode N (Hz)
//   log_decrement N           logarithmic decrement of mode N of a rotor analysis
//   critical_speed N          N-th critical speed of a campbell analysis (rpm), ascending
//   instability_onset         onset of instability of a campbell analysis (rpm)
//   unbalance_amplitude POINT at RPM   orbit semi-major axis of POINT at RPM (m)
//   runup peak POINT          largest per-revolution amplitude of POINT in a run-up (m)
//   runup speed_at_peak POINT the speed of the revolution where it occurs (rpm)
//   runup eccentricity BEARING the largest eccentricity ratio of a nonlinear journal (-)
//   runup end_speed          the speed at the end of the run (rpm; a driven speed's result)
//   runup film_torque        the nonlinear films' drag torque at the end of the run (N m)
//   runup rub_force RUB      the largest normal force of a rub station (N)
//   runup rub_torque RUB     the largest friction torque of a rub station on the spin (N m)
//   runup rub_time RUB       how long a rub station was in contact (s)
//   rigid_body PROPERTY       mass, com_x, J_com, Jp, f1, f2 (Hz), n1, n2, FA1, FB1, FA2, FB2
//                             (N, per unit modal amplitude) of a rigid-body analysis
// those of the response-spectrum analysis (structure/SpectrumQuantity.hpp):
//   spectrum displacement POINT DOF   combined peak displacement (m, rad) relative to the ground
//   spectrum reaction SUPPORT DOF     combined peak reaction (N, N m)
//   spectrum base_shear x|y|z         combined peak total force into the ground (N)
//   spectrum member NAME COMP max     largest combined peak of a resultant along a member
//   effective_mass N x|y|z            effective modal mass of mode N (kg)
//   captured_mass x|y|z               the modes' effective masses over the total mass
// and of the base-motion analysis (the largest over its frequencies):
//   base_motion transmissibility POINT max   |absolute acceleration| / |ground's|, along the
//                                            ground's direction
//   base_motion relative POINT max   |displacement relative to the ground| (m)
//   base_motion absolute POINT max   |absolute displacement| (m)
//   base_motion base_force max       |force the ground exerts| (N)
//   base_motion peak_frequency POINT   the frequency (Hz) of the largest transmissibility
// and those of the crank-slider analysis (CrankQuantity.hpp):
//   crank PROPERTY [at LAMBDA]   a figure of the mechanism, or a row of its harmonic table
//   crank PROPERTY at PHI deg    the motion or a load of the first crank at crank angle PHI
#pragma once

#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

#include "fem/model/Dof.hpp"

namespace beamrotor {

struct Quantity {
  enum class Kind {
    reaction,
    displacement,
    frequency,
    maxStress,
    maxShear,
    maxMoment,
    maxDisplacement,
    memberForce,
    memberDeflection,
    bucklingFactor,  // buckling analyses
    sectionProperty,  // any analysis of the beams
    logDecrement,
    criticalSpeed,
    instabilityOnset,
    unbalanceAmplitude,
    rigidBody,  // rotor analyses
    levelOne,   // level1-stability: `level1 PROPERTY`
    padMode,    // rotor: `pad_mode N PROPERTY`, the pads' own modes (pad_tilts: dofs)
    runUp,      // run-up: `runup peak|speed_at_peak POINT`
    crankSlider,  // crank-slider analyses (CrankQuantity.hpp)
    torsion,      // torsion analyses of a train (TorsionQuantity.hpp)
    historyMax,
    historyMin,
    historyMaxAbs,
    historyAt,  // transient analyses
    resultantAt,
    movingMax,
    movingMin,     // moving-load analyses: the envelope of `inner`
    spectrum,      // response-spectrum: `spectrum WHAT ...` (property: what)
    effectiveMass,  // response-spectrum: effective_mass N DIR (mode N), captured_mass DIR (mode 0)
    baseMotion      // base-motion: `base_motion PROPERTY [POINT] ...`
  };
  Kind kind = Kind::reaction;
  std::string target;    ///< support (reaction), point (displacement) or history name
  std::string timeText;  ///< historyAt: the time as written
  double time = 0;       ///< historyAt: s (set by the deck reader)
  Dof dof = Dof::uy;
  /// displacement: the node's own value, or the rotation of the beam end on one side of it.
  enum class Side { node, left, right };
  Side side = Side::node;
  int mode = 1;  ///< frequency, buckling_factor, log_decrement, critical_speed: 1-based number
  double rpm = 0;        ///< unbalance_amplitude: the speed (rpm)
  std::string property;  ///< rigid_body, level1, pad_mode: which property; torsion: torque or twist;
                         ///< memberForce: N, Vy, Vz, T, My, Mz; spectrum: displacement,
                         ///< reaction, base_shear or member (its component in `extreme`);
                         ///< sectionProperty: one of kSectionProperties
  std::string extreme;   ///< memberForce: max, min or maxabs
  double lambda = 0;     ///< crankSlider `... at LAMBDA`: the table row; 0 for the mechanism's own
  std::optional<double> crankAngle;  ///< crankSlider `... at PHI deg`: the crank angle (rad)
  std::string text;      ///< as written, for reports
  /// movingMax, movingMin: the quantity whose envelope it is (a reaction, displacement or
  /// resultant at a point).
  std::shared_ptr<const Quantity> inner;
  // Which analyses give it: the rows of problems/deck/AnalysisKinds.hpp say.
};

/// The properties `section NAME PROPERTY` names, in the steel tables' axes.
inline constexpr const char* kSectionProperties[] = {"A",     "Iy",    "Iz",    "It",
                                                     "Wel_y", "Wel_z", "Wpl_y", "Wpl_z"};

/// ux..rz, or the force/moment names fx fy fz mx my mz for the same dofs; throws
/// std::invalid_argument for another word.
Dof parseComponent(const std::string& word);

/// Parses the phrase; throws std::invalid_argument saying what is wrong and what is allowed.
/// Names are not checked here (the deck reader knows them).
Quantity parseQuantity(const std::string& text);

}  // namespace beamrotor
