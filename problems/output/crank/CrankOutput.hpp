// The files of a crank-slider analysis (problems/scenes/README.md section 3): its results.json
// entry, the tables against the crank angle, of the inertia harmonics and of the harmonic
// coefficients against lambda, and the charts of the SNT-32 paper's Fig. 2 (slider position,
// velocity and acceleration against the crank angle, exact and two-term) and Fig. 4 (the
// harmonics of the inertia force, one crank and all cranks).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "problems/deck/OutputUnits.hpp"
#include "problems/output/files/CsvTable.hpp"
#include "problems/output/JsonWriter.hpp"
#include "problems/run/RunResult.hpp"

namespace beamrotor {

/// <stem>_motion.csv, <stem>_harmonics.csv and, with lambdas, <stem>_lambda_table.csv.
std::vector<CsvTable> crankTables(const CrankSliderOutcome& c, const std::string& stem);

/// The analysis' entry in results.json (a.crank set).
Json crankJson(const AnalysisOutcome& a, const std::string& stem);

/// The two charts, <stem>_kinematics and <stem>_inertia_harmonics, drawn from the motion table
/// as written in `units` (inUnits).
void drawCrankCharts(const std::filesystem::path& dir, const CrankSliderOutcome& c,
                     const std::string& stem, const std::string& caption,
                     const OutputUnits& units = {});

}  // namespace beamrotor
