// Whole-number options read strictly: CLI11 alone converts loosely (`--seed -1` and
// `--seed 18446744073709551616` both became 18446744073709551615, `0x10` was 16) or answers a
// bare "Could not convert". Each count, seed and size on the command line is checked here
// first, as text, by type and range, and a refusal names the option.
#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <string>

namespace beamrotor::cli {

/// Why `text` is not a whole number from low to high written in decimal digits (no sign,
/// fraction, exponent, hexadecimal or spaces), or "" when it is.
std::string wholeNumberProblem(const std::string& text, std::uint64_t low, std::uint64_t high);

/// The same as a CLI11 check: the option is refused (exit 2) with "--NAME: <why>".
CLI::Validator wholeNumber(std::uint64_t low, std::uint64_t high);

}  // namespace beamrotor::cli
