// The damped modes of a rotor analysis as a reader pictures them: per mode an oblique view along
// the shaft with each node's orbit ellipse (coloured by its sense, forward or backward whirl, an
// arrow head where it starts, so the sense also reads in grey), the shaft's deflected line at
// the start of the period, the undeformed centre line, disks as bars at their stations and
// bearings and supports as symbols; the mode's frequency, log decrement and whirl in its title.
#pragma once

#include <string>

#include "fem/model/Model.hpp"
#include "fem/rotor/RotorResults.hpp"
#include "problems/deck/OutputUnits.hpp"
#include "problems/output/files/CsvTable.hpp"
#include "problems/output/files/Gnuplot.hpp"

namespace beamrotor {

/// The orbits sampled for the chart: per mode, angle step and node (in the order of x) one
/// row: mode, node (1-based), x (m), angle (deg, omega t from 0 to 360), uy, uz (the orbit
/// point Re((uy, uz) e^{i angle}) in the mode's scale, its largest orbit's semi-major axis 1),
/// duy, duz (to the next angle's point) and whirl (+1 forward, -1 backward, 0 planar: the
/// node's own sense).
CsvTable modeOrbitsTable(const std::string& title, const RotorModesResult& r, const Model& model);

/// The panels of the modes of `r` from a modeOrbitsTable in csvFile; disks (point inertias with
/// a polar moment: bars sized by their radius of gyration) and bearings (triangles) and
/// supports (squares, both under the shaft at the panel's foot) taken from the model; x along
/// the shaft and the speed in the user's `units` where set (the table's x then holds them).
ChartScript modeOrbitsChart(const std::string& caption, const std::string& chartName,
                            const RotorModesResult& r, const Model& model,
                            const CsvTable& orbits, const std::string& csvFile,
                            const OutputUnits& units = {});

}  // namespace beamrotor
