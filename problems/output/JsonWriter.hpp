// results.json and sweep.json: the stable, machine-read summary of a run. Keys keep the
// order they are written in (nlohmann::ordered_json) so a person can read the file too.
//
// results.json:
//   deck {name, path}, model {nodes, elements, dofs, dimension},
//   analyses [ static: {type, name, reactions {support: {fx ... mz}}, displacements
//              {point: {ux ... rz, at a hinge rz_left, rz_right ...}}, max_stress and max_shear
//              {value, x, element, section}, [contacts {name: {dof, active, value, bound, gap,
//              force}}, active_set_iterations], [one_way_members {name: {slack, force,
//              elongation}}], rcond (of the diagonally scaled K),
//              round_off (measured bound of the solution's relative error), time_s, files}
//            | modal:  {type, name, frequencies_hz [...], total_mass_kg {ux ..}, modes [{mode,
//              frequency_hz, description, effective_mass_kg {ux ..}, effective_mass_ratio
//              {ux ..}, energy_share {ux .. rz}}], time_s, files}
//            | buckling, and a static analysis' second_order: see StabilityOutput.hpp
//            | transient: see TransientJson.hpp ],
//            | rotor, campbell, unbalance, rigid-body: see RotorJson.hpp ],
//   checks [{name, quantity, computed, reference, rel_error, tolerance, pass}],
//   skipped_checks [name], parameters {name: value}, [reported {name: value}], seconds,
//   beamrotor_version.
// Only the components a model carries appear (a planar model has no fz, my, uz ...).
// sweep.json: parameter, values, model, runs [{value, directory, parameters, reported, analyses
// (type, name, reactions, max_stress, max_shear, second_order | frequencies_hz | maxima |
// load_factors), checks}], worst
// {analysis: {max_stress, max_shear}}: each the largest over the runs, with at {parameter: value}.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "problems/output/structure/LineSampling.hpp"
#include "problems/output/structure/StaticExtremes.hpp"
#include "problems/run/RunResult.hpp"

namespace beamrotor {

using Json = nlohmann::ordered_json;

/// Adds `key` to `object`, which must not hold it yet, and returns its value: without the
/// ordered map's search for the key (linear in its size, so quadratic over a frame's 10^4
/// members or named points).
Json& appendNew(Json& object, std::string key, Json value = Json::object());

/// An empty object with storage for `entries` entries. ordered_json keeps an object's entries
/// in a vector of pairs whose keys are const, so growing it copies every subtree it holds (a
/// run's analyses, a static analysis' cases): objects that will hold large ones start with
/// room for all their entries.
Json objectWithRoom(std::size_t entries);

/// Reactions per support: {support: {fx ... mz}}, the components the support holds.
Json reactionsJson(const StaticResult& r);
/// The same of any such forces by name, e.g. springs' and bearings' (StaticResult::elementForces).
Json forcesJson(const std::vector<ReactionComponent>& forces);

/// results.json of one run. `extremes[i]` are those of run.analyses[i] (staticExtremes of its
/// own solution and of each load case and combination; empty for other kinds): the largest
/// stresses, member extremes and largest displacements are read from them.
Json runJson(const RunResult& run, const std::vector<AnalysisExtremes>& extremes);
/// The same, the extremes computed here.
Json runJson(const RunResult& run);


/// sweep.json from the values and each value's results.json (runDocs) and sub-directory
/// (empty: none, the entry names no directory).
Json sweepJson(const SweepResult& sweep, const std::vector<Json>& runDocs,
               const std::vector<std::string>& directories);

/// Throws std::runtime_error naming where the first NaN or infinity sits, e.g.
/// "results.json: analyses/0/max_stress/value would be nan" (nlohmann would write null).
void requireFiniteNumbers(const Json& doc, const std::string& document);

/// Writes doc (indented) to file; throws std::runtime_error when it cannot.
void writeJson(const Json& doc, const std::filesystem::path& file);

}  // namespace beamrotor
