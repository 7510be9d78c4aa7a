// The quantities a deck's checks compare with closed forms, written as short phrases:
//   reaction SUPPORT DOF      support reaction (N, N m); DOF ux uy uz rx ry rz or fx .. mz
//   displacement POINT DOF    displacement (m) or rotation (rad) of a named point
//   frequency N               natural frequency of mode N (Hz), N from 1
//   stress max                largest |normal stress| on the outer fibres of any beam (Pa)
//   shear max                 largest transverse shear stress in any beam (Pa), fem/ShearStress
//   moment max                largest bending moment magnitude in any beam (N m)
#pragma once

#include <stdexcept>
#include <string>

#include "fem/Dof.hpp"
#include "fem/Model.hpp"
#include "problems/RunResult.hpp"

namespace beamrotor {

struct Quantity {
  enum class Kind { reaction, displacement, frequency, maxStress, maxShear, maxMoment };
  Kind kind = Kind::reaction;
  std::string target;  ///< support (reaction) or point (displacement) name
  Dof dof = Dof::uy;
  int mode = 1;        ///< frequency: 1-based mode number
  std::string text;    ///< as written, for reports

  /// The analysis type whose result it reads: "static" or "modal".
  std::string analysisType() const { return kind == Kind::frequency ? "modal" : "static"; }
};

/// Parses the phrase; throws std::invalid_argument saying what is wrong and what is allowed.
/// Names are not checked here (the deck reader knows them).
Quantity parseQuantity(const std::string& text);

/// The quantity's value in a solved analysis of model. Throws std::invalid_argument when the
/// analysis lacks it (wrong type, too few modes, unknown name).
double measure(const Quantity& q, const AnalysisOutcome& outcome, const Model& model);

}  // namespace beamrotor
