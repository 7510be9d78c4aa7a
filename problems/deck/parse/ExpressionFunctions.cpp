#include "problems/deck/parse/ExpressionFunctions.hpp"

#include <muParser.h>

#include <stdexcept>
#include <string>

#include "problems/scenes/CrankSlider.hpp"

namespace beamrotor {

namespace {

/// The crank's exact kinematics at phi, or a parser error naming `function`.
crank::PhiDerivatives crankAt(const char* function, double r, double l, double phi) {
  try {
    return crank::exactInPhi(crank::makeGeometry(r, l), phi);
  } catch (const std::invalid_argument& e) {
    throw mu::ParserError(std::string(function) + "(r, l, phi): " + e.what());
  }
}

double crankPosition(double r, double l, double phi) {
  return crankAt("crank_position", r, l, phi).x;
}

double crankRodAngle(double r, double l, double phi) {
  return crankAt("crank_rod_angle", r, l, phi).beta;
}

}  // namespace

void defineDeckFunctions(mu::Parser& parser) {
  parser.DefineFun("crank_position", crankPosition);
  parser.DefineFun("crank_rod_angle", crankRodAngle);
}

}  // namespace beamrotor
