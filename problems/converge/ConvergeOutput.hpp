// The files of `beamrotor converge`, in the output directory (replaced as a whole):
//
// convergence.json (other tools read it, e.g. the verification report; keep it stable):
//   deck {name, path}, quantity (deck syntax, e.g. "frequency 1"), analysis (its name),
//   check (the check whose reference is the closed form, or null), choice (how the quantity
//   was chosen), refinement ("mesh", or "time step" for a transient quantity),
//   reference_kind ("closed form" or "richardson": extrapolated per method from its three
//   finest levels, an estimate),
//   methods [{name ("eb-consistent", "eb-lumped", "timoshenko", "timoshenko-linear-full",
//             "timoshenko-linear-reduced"; "time-step" in a time-step study), label, reference,
//             extrapolation_order (or null), levels [{level, elements, dofs (free), steps (time
//             steps; 0 in mesh
//                      studies), runs, time_s {assembly, factor, solve,
//                      total} (medians over the runs; modal: the factorisation is inside
//                      solve), value, rel_error, order (observed against the previous level,
//                      or null)}],
//             failure (null, or why the method stopped before the last level)}],
//   beamrotor_version.
// convergence_<method name>.csv: one row per level solved: level, elements, dofs, steps, assembly,
//   factor, solve, total [s], value [the quantity's unit], rel_error; in the output units.
// convergence_dofs.{gp,svg,png}: relative error against free dofs, log-log, one line per
//   method (against time steps in a time-step study); convergence_time.{gp,svg,png}: relative error
//   against wall time (total).
#pragma once

#include <filesystem>

#include "problems/converge/ConvergeStudy.hpp"
#include "problems/deck/OutputUnits.hpp"
#include "problems/output/files/CsvTable.hpp"
#include "problems/output/JsonWriter.hpp"

namespace beamrotor {

/// convergence.json's document.
Json convergenceJson(const ConvergeStudy& study);

/// convergence_<method>.csv's table of one series, its values in `unit` (the study's).
CsvTable convergenceTable(const ConvergeSeries& series, const FieldUnit& unit = {});

/// Every series' table in `units` (inUnits), in method order.
std::vector<CsvTable> convergenceTables(const ConvergeStudy& study, const OutputUnits& units);

/// Writes the files above into dir (atomically), the tables (values, times) and the time axis
/// in `units` (inUnits; convergence.json stays as measured). Throws std::runtime_error when it
/// cannot.
void writeConvergenceOutputs(const ConvergeStudy& study, const std::filesystem::path& dir,
                             const OutputUnits& units = {});

}  // namespace beamrotor
