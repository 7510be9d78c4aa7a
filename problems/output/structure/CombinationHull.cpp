// The load combinations that can govern an envelope (see CombinationHull.hpp).
#include "problems/output/structure/CombinationHull.hpp"

#include "fem/assembly/ExtremePoints.hpp"

namespace beamrotor {

std::vector<bool> combinationsThatCanGovern(const std::vector<CaseOutcome>& cases) {
  std::vector<std::string> loadCases;
  std::vector<std::size_t> combinations;
  for (std::size_t k = 0; k < cases.size(); ++k)
    if (cases[k].combination)
      combinations.push_back(k);
    else
      loadCases.push_back(cases[k].name);
  // Each combination's factor of each load case, summed as the combination sums them.
  Eigen::MatrixXd factors =
      Eigen::MatrixXd::Zero(Eigen::Index(combinations.size()), Eigen::Index(loadCases.size()));
  for (std::size_t i = 0; i < combinations.size(); ++i)
    for (const auto& [name, factor] : cases[combinations[i]].factors)
      for (std::size_t j = 0; j < loadCases.size(); ++j)
        if (loadCases[j] == name) factors(Eigen::Index(i), Eigen::Index(j)) += factor;
  const std::vector<bool> extreme = extremePoints(factors);
  std::vector<bool> out(cases.size(), false);
  for (std::size_t i = 0; i < combinations.size(); ++i) out[combinations[i]] = extreme[i];
  return out;
}

}  // namespace beamrotor
