// Charts of the rotor analyses, as gnuplot scripts over their CSV tables: the Campbell
// diagram and the unbalance response (amplitude and phase against speed).
#pragma once

#include <optional>

#include "problems/deck/OutputUnits.hpp"
#include <string>
#include <vector>

#include "problems/output/files/CsvTable.hpp"
#include "problems/output/files/Gnuplot.hpp"
#include "problems/output/rotor/OperatingBand.hpp"

namespace beamrotor {

/// Each chart's axes are in the units named below, or in `units` where the user set them (the
/// tables then hold them; OutputUnits.hpp).
///
/// Whirl frequency (Hz) of each line against speed (rpm) from a campbellTable in csvFile,
/// coloured by whirl (forward, backward, planar), an order x speed line dashed per order (the
/// first, that of the critical speeds, darkest), and the crossings
/// from a criticalSpeedsTable in criticalFile marked and labelled in rpm; the
/// operating band shaded when given.
ChartScript campbellDiagram(const std::string& caption, const std::string& chartName,
                            const CsvTable& campbell, const std::string& csvFile,
                            const CsvTable& critical, const std::string& criticalFile,
                            const std::vector<double>& orders,
                            const std::optional<OperatingBand>& band = std::nullopt,
                            const OutputUnits& units = {});

/// Two panels against speed (rpm) from an unbalanceTable in csvFile: the orbit semi-major
/// axis (um, log scale) and the phase of uy (deg, unwrapped: continuous through the criticals,
/// a lag negative), one curve per response point; the operating band shaded when given.
/// Above `unstableFromRpm` (the onset of instability) the speeds are shaded and marked
/// "unstable": a steady response there is not what the rotor does. The amplitude axis spans at
/// most kAmplitudeDecades below the largest amplitude; each curve is a line with a marker every
/// few rows, each drawn thinner than the one before, so that equal curves show one within the
/// other.
ChartScript unbalanceResponseChart(const std::string& caption, const std::string& chartName,
                                   const CsvTable& response, const std::string& csvFile,
                                   const std::vector<std::string>& points,
                                   const std::optional<OperatingBand>& band = std::nullopt,
                                   std::optional<double> unstableFromRpm = std::nullopt,
                                   const OutputUnits& units = {});
/// Decades of amplitude the unbalance chart shows below its largest.
inline constexpr double kAmplitudeDecades = 4;

/// Two panels against frequency (Hz) from a frequencyResponseTable in csvFile: the receptance
/// magnitude (log scale) and its phase (deg, unwrapped as on the unbalance chart); `what` names
/// it ("B uy / A uy").
ChartScript frequencyResponseDiagram(const std::string& caption, const std::string& chartName,
                                     const CsvTable& response, const std::string& csvFile,
                                     const std::string& what, const OutputUnits& units = {});

}  // namespace beamrotor
