// The operating speed range on a rotor chart against speed: the range shaded, and around it
// the separation margins API 684 / API 617 require of the critical speeds next to it (see
// fem/rotor/Api684.hpp), shaded lighter, so a reader sees at a glance whether a line or a peak
// falls inside the range or inside its margins.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "fem/rotor/Api684.hpp"
#include "fem/rotor/RotorResults.hpp"

namespace beamrotor {

/// Speeds in rpm; margins in % (0: none required, or no critical speed on that side).
struct OperatingBand {
  double minRpm = 0, maxRpm = 0;
  double marginBelow = 0;  ///< the largest margin required of a critical below the range
  double marginAbove = 0;  ///< the largest margin required of a critical above it
};

/// The band from the critical speeds of a Campbell diagram: each one's amplification factor is
/// 1 / (2 zeta) of its line's damping ratio there (unbounded for zeta <= 0: the largest margin).
OperatingBand bandOfCriticalSpeeds(const OperatingRange& range,
                                   const std::vector<CriticalSpeed>& critical);

/// The band from an API 684 reading of an unbalance response: each peak's own required margin.
OperatingBand bandOfPeaks(const OperatingRange& range,
                          const std::vector<std::vector<ResponsePeak>>& peaks);

/// gnuplot commands shading the band on a chart whose x axis is speed in rpm times
/// `speedFactor` (another speed unit: SpeedAxes.hpp) behind the data, with its key entries
/// returned as plot clauses (", NaN with boxes ..."); objects are numbered from `firstObject`.
struct BandCommands {
  std::string setup;                ///< before the plot command
  std::string keyEntries;           ///< appended to the plot command
  std::vector<std::string> titles;  ///< the key's titles (to size the key)
};
BandCommands operatingBandCommands(const std::optional<OperatingBand>& band,
                                   double speedFactor = 1, int firstObject = 50);

}  // namespace beamrotor
