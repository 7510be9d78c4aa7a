// What a response-spectrum analysis writes: its tables (modes with participation and
// effective masses, combined peak displacements, reactions and section forces along the
// members), its results.json entry, the spectrum chart with the modes on it, and the VTK file
// of the combined peak displacements.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "fem/modal/ResponseSpectrum.hpp"
#include "problems/output/JsonWriter.hpp"
#include "problems/output/files/CsvTable.hpp"

namespace beamrotor {

/// <stem>_spectrum_modes.csv, <stem>_spectrum_displacements.csv,
/// <stem>_spectrum_reactions.csv (with supports) and <stem>_spectrum_members.csv (with line
/// elements), each table titled by its file name.
std::vector<CsvTable> spectrumTables(const ResponseSpectrumResult& r, const Model& model,
                                     const std::string& stem);

/// The analysis' results.json entry.
Json spectrumJson(const std::string& type, const std::string& name,
                  const ResponseSpectrumResult& r, const Model& model);

/// <stem>_spectrum.png: Sa against the period with each mode's (T, Sa) marked; and
/// <stem>_spectrum.vtu, the combined peak displacements.
void writeSpectrumFiles(const std::filesystem::path& dir, const ResponseSpectrumResult& r,
                        const Model& model, const std::string& stem, const std::string& caption,
                        bool charts);

/// The name of <stem>'s VTK file of combined peak displacements.
std::string spectrumVtu(const std::string& stem);

}  // namespace beamrotor
