// The exact extrema of the stress resultants along line elements. Within an element the
// resultants are polynomials of known degree in the position (SectionForceSeries: forces at
// most linear, moments at most quadratic under uniform span loads), so the largest bending
// moment, normal stress and shear stress lie at an end or where a derivative vanishes: found
// here from those polynomials, not from samples. Every output that reports a largest value
// (check quantities, results.json, the summary, VTK) reads these.
#pragma once

#include <optional>
#include <vector>

#include "fem/assembly/Polynomial.hpp"
#include "fem/assembly/Recovery.hpp"
#include "fem/model/LineElement.hpp"
#include "fem/model/Model.hpp"
#include "fem/model/Results.hpp"

namespace beamrotor {

/// The largest value of one quantity on one element and where it is.
struct BeamPeak {
  int element = -1;  ///< index into model.elements()
  double s = 0;      ///< fraction of the element's length, 0..1
  double value = 0;  ///< NaN when some resultant of the element is not finite
};

/// An element's largest outer-fibre normal stress (maxNormalStress, Pa), transverse shear
/// stress (maxShearStress, Pa) and bending moment magnitude hypot(My, Mz) (N m).
struct ElementPeaks {
  BeamPeak stress, shear, moment;
};

/// The peaks of one element from its resultants along it.
ElementPeaks elementPeaks(const LineElement& element, const SectionForceSeries& forces);

/// The peaks of every line element of a static solution, in element order.
std::vector<ElementPeaks> elementPeaks(const LoadedSolution& solution);

/// The peaks of the line elements of a static solution that can hold the solution's largest
/// stress, shear stress or moment, in element order (a load case's or combination's, whose
/// only the largest is reported; elementPeaks for every element's). An element is left out
/// when an upper bound of each of its three kinds over the element (from its resultants'
/// Bernstein bounds, elementBounds in the .cpp; of a combination, its cases' weighted) is
/// below the peak of that kind of one of the few elements with the largest bounds: its own
/// peaks are then strictly smaller than the largest, so largestPeak of
/// every kind over these is the same BeamPeak, to the bit, as over every element's, first of
/// equal values and NaN included (an element with a value that is not finite has no finite
/// bound and is kept).
std::vector<ElementPeaks> peaksThatCanGovern(const LoadedSolution& solution);

/// The largest of one kind over the elements (the first on ties); a value that is not finite
/// anywhere makes the result NaN, so a check on it fails instead of reading a smaller number.
/// nullopt without line elements.
std::optional<BeamPeak> largestPeak(const std::vector<ElementPeaks>& peaks,
                                    BeamPeak ElementPeaks::*kind);

/// Places in [0, 1] held in place: the ends and the zeros of a polynomial of degree <= 10 and
/// of its derivatives (appendZeros) fit.
using ZeroPlaces = InPlaceDoubles<128>;

/// Appends the real zeros in [0, 1] of p, together with the zeros of its derivatives there (so
/// even-multiplicity zeros are among them): every place where it can change sign or touch zero.
void appendZeros(const Polynomial& p, ZeroPlaces& out);
void appendZeros(const Polynomial& p, std::vector<double>& out);

/// appendZeros of the polynomial c[0] + c[1] s + ... (degree <= 10) into a new list. Exposed
/// for the tests.
std::vector<double> zerosInUnitInterval(const std::vector<double>& c);

}  // namespace beamrotor
