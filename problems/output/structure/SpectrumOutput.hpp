// What a response-spectrum analysis writes: its tables (modes with participation and
// effective masses, combined peak displacements, reactions and section forces along the
// members), its results.json entry, the spectrum chart with the modes on it, and the VTK file
// of the combined peak displacements.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "fem/assembly/MemberExtrema.hpp"
#include "fem/modal/ResponseSpectrum.hpp"
#include "problems/deck/OutputUnits.hpp"
#include "problems/output/JsonWriter.hpp"
#include "problems/output/files/CsvTable.hpp"

namespace beamrotor {

/// <stem>_spectrum_modes.csv, <stem>_spectrum_displacements.csv,
/// <stem>_spectrum_combinations.csv (each combination of the directions: base force, largest
/// displacements, reactions and members' largest resultants, the governing one marked),
/// <stem>_spectrum_reactions.csv (with supports) and <stem>_spectrum_members.csv (with line
/// elements), each table titled by its file name. The reactions table's rows are in `units`
/// already (each names its unit: forces and moments share its columns); the other tables'
/// columns are in SI, each named, for inUnits.
std::vector<CsvTable> spectrumTables(const ResponseSpectrumResult& r, const Model& model,
                                     const std::string& stem, const OutputUnits& units);

/// The analysis' results.json entry.
Json spectrumJson(const std::string& type, const std::string& name,
                  const ResponseSpectrumResult& r, const Model& model);

/// <stem>_spectrum.png: Sa against the period with each mode's (T, Sa) marked, in `units`;
/// and <stem>_spectrum.vtu, the combined peak displacements (SI).
void writeSpectrumFiles(const std::filesystem::path& dir, const ResponseSpectrumResult& r,
                        const Model& model, const std::string& stem, const std::string& caption,
                        bool charts, const OutputUnits& units);

/// The largest peak of resultant `c` at the stations of `elements` (a member's).
double memberPeak(const PeakResponse& p, const std::vector<int>& elements, ForceComponent c);

/// The combination of the directions that gives the largest value of the quantity `value`
/// reads from a peak response (the first when several tie): its index in r.combinations.
template <class Read>
std::size_t governingCombination(const ResponseSpectrumResult& r, Read value) {
  std::size_t best = 0;
  for (std::size_t i = 1; i < r.combinations.size(); ++i)
    if (value(r.combinations[i].peak) > value(r.combinations[best].peak)) best = i;
  return best;
}

/// The name of <stem>'s VTK file of combined peak displacements.
std::string spectrumVtu(const std::string& stem);

}  // namespace beamrotor
