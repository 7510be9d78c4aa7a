// The CSV tables of one run: static fields along the line, the list of modes, and the
// display-scaled mode shapes along the line (which the mode-shape chart plots).
#pragma once

#include <string>
#include <vector>

#include "problems/output/files/CsvTable.hpp"
#include "problems/output/structure/LineSampling.hpp"

namespace beamrotor {

/// One row per station: x (m, along the line), ux uy uz (m), rx ry rz (rad) in the global
/// frame; N, Vy, Vz (N), T, My, Mz (N m) in the element frame (see SectionForces); stress
/// (Pa, largest |normal stress| of the section); element (index into model.elements()).
CsvTable staticFieldsTable(const std::string& title, const std::vector<StaticStation>& stations);

/// One row per force component of a spring or bearing (StaticResult::elementForces): spring
/// (its name), at (its point, or the node's number), component (fx .. mz), and the force (N)
/// or moment (N m) it exerts on the structure, the other cell empty.
CsvTable springForcesTable(const std::string& title, const Model& model,
                           const StaticResult& statics);

/// The support reactions (StaticResult::reactions) in the same columns, led by `support`;
/// `force` or `moment` left out when no support holds a component of its kind.
CsvTable reactionsTable(const std::string& title, const Model& model, const StaticResult& statics);

/// One row per mode: mode (1-based), frequency (Hz), description, effective masses (kg) and
/// their ratios to the total mass along ux uy uz (0 where the total is 0), energy shares.
CsvTable modesTable(const std::string& title, const ModalResult& modal);

/// One row per station along the line: x (m), then for every mode k columns mode<k>_ux,
/// mode<k>_uy, mode<k>_uz: translations of the shape scaled by displayModeShape; a torsional
/// mode (isTorsionalShape) also mode<k>_rx (or _ry, _rz: its chartedDof), largest 1. A frame's
/// table instead has one row per place along each member (kIntervalsPerElement pieces of
/// each element, the member's rows together from its start): member, its coordinates x, y, z
/// (m), and each mode's mode<k>_ux, _uy, _uz (displayModeShape's scale).
CsvTable modeShapesTable(const std::string& title, const Model& model, const ModalResult& modal);

/// Name of a mode-shape column, e.g. "mode2_uy", "mode3_rx".
std::string modeShapeColumn(int mode, Dof dof);

}  // namespace beamrotor
