// Random numbers for design studies, reproducible across compilers and library versions: the
// engine is std::mt19937_64 (whose output sequence the C++ standard fixes for a given seed), and
// the transforms to uniform and normal variates are our own, because the standard library's
// distributions may differ from one implementation or version to another.
#pragma once

#include <cstdint>
#include <random>

namespace beamrotor {

/// A uniform variate in the open interval (0, 1) from one 64-bit draw: the top 53 bits, centred
/// in their cell ((k + 1/2) / 2^53), so neither 0 nor 1 ever comes out.
double openUniform(std::mt19937_64& engine);

/// A whole number in [0, n) without modulo bias (rejection of the incomplete last block).
std::uint64_t uniformIndex(std::mt19937_64& engine, std::uint64_t n);

/// The standard normal distribution function Phi(x) = erfc(-x / sqrt 2) / 2.
double normalCdf(double x);

/// The standard normal quantile Phi^-1(p), 0 < p < 1: the rational starting value of
/// Abramowitz and Stegun 26.2.23 (|error| < 4.5e-4), refined by Halley steps on
/// Phi(x) - p to full double precision (each step triples the correct digits).
double normalQuantile(double p);

}  // namespace beamrotor
