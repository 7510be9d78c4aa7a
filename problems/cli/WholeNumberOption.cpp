#include "problems/cli/WholeNumberOption.hpp"

#include <charconv>

namespace beamrotor::cli {

std::string wholeNumberProblem(const std::string& text, std::uint64_t low, std::uint64_t high) {
  const std::string expected = "expected a whole number from " + std::to_string(low) + " to " +
                               std::to_string(high) + ", got '" + text + "'";
  if (text.empty() || text.find_first_not_of("0123456789") != std::string::npos)
    return expected + (text.find_first_of(".eE") != std::string::npos && !text.empty() &&
                               text.find_first_not_of("0123456789.eE+-") == std::string::npos
                           ? " (not a whole number)"
                       : !text.empty() && text[0] == '-' ? " (negative)"
                                                         : "");
  std::uint64_t value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error == std::errc::result_out_of_range || value > high) return expected + " (too large)";
  if (value < low) return expected + " (too small)";
  return {};
}

CLI::Validator wholeNumber(std::uint64_t low, std::uint64_t high) {
  return CLI::Validator(
      [low, high](std::string& text) { return wholeNumberProblem(text, low, high); },
      "INT in [" + std::to_string(low) + " - " + std::to_string(high) + "]");
}

}  // namespace beamrotor::cli
