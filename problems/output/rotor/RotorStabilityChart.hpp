// The stability chart of a Campbell analysis: the whirl frequencies coloured by their
// logarithmic decrement, and the decrements themselves against speed with the onset of
// instability marked.
#pragma once

#include <optional>
#include <string>

#include "problems/deck/OutputUnits.hpp"
#include "problems/output/files/CsvTable.hpp"
#include "problems/output/files/Gnuplot.hpp"
#include "problems/output/rotor/OperatingBand.hpp"

namespace beamrotor {

/// Two panels against speed (rpm) from a campbellTable in csvFile: each line's whirl frequency
/// (Hz) coloured by its log decrement (red below zero: growing; green well damped), and each
/// line's log decrement with the zero line (each line its own colour and dash); onsetRpm,
/// when given, drawn as a vertical line; the operating band shaded when given. Speed and
/// frequency in the user's `units` where set (SpeedAxes.hpp).
ChartScript stabilityDiagram(const std::string& caption, const std::string& chartName,
                             const CsvTable& campbell, const std::string& csvFile,
                             std::optional<double> onsetRpm,
                             const std::optional<OperatingBand>& band = std::nullopt,
                             const OutputUnits& units = {});

}  // namespace beamrotor
