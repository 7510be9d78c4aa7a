// The section catalogue (problems/deck/catalog): every row's properties computed from its
// dimensions against the steel tables' printed values (a documented sample of rows of every
// family, to their printed digits) and, for the hollow sections, every row against closed
// forms of their own; catalogue sections in decks: a cantilever of IPE 300 bent about its
// strong and its weak axis against P L^3 / (3 E I) with the printed I, and an unknown
// designation refused at its line with the nearest one suggested.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <fstream>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "fem/model/StandardSections.hpp"
#include "problems/deck/catalog/SectionCatalog.hpp"
#include "problems/deck/parse/DeckError.hpp"
#include "problems/deck/parse/Units.hpp"
#include "problems/run/Study.hpp"
#include "tests/Helpers.hpp"
#include "tests/problems/DeckTestSupport.hpp"

using namespace beamrotor;

namespace {

/// A printed value and half a unit of its last printed digit (both in the table's unit).
struct Printed {
  double value = 0, halfUnit = 0;
};

/// "5.24" -> 5.24 +- 0.005; an integer's trailing zeros are not digits unless fewer than three
/// remain (tables print at least three): "1033" -> +- 0.5, "18260" -> +- 5, "8030" -> +- 5.
Printed printed(const std::string& text) {
  const double v = std::stod(text);
  const auto point = text.find('.');
  if (point != std::string::npos)
    return {v, 0.5 * std::pow(10.0, -double(text.size() - point - 1))};
  const int digits = int(text.size());
  const int significant = std::max(3, int(text.find_last_not_of('0')) + 1);
  return {v, 0.5 * std::pow(10.0, std::max(0, digits - significant))};
}

/// The largest |computed / printed - 1| per property of a family, for the report below.
struct Worst {
  std::string property;
  double relative = 0;
  std::string row;
};

void compare(const std::string& row, const std::string& property, double computed,
             const std::string& text, double unit, double extra, std::vector<Worst>& worst) {
  const Printed p = printed(text);
  const double value = computed / unit;
  CAPTURE(row);
  CAPTURE(property);
  CAPTURE(value);
  CAPTURE(text);
  // Within half a unit of the last printed digit, plus `extra` (relative) where the table's
  // formula differs from ours (the torsion constant, below).
  CHECK(std::abs(value - p.value) <= p.halfUnit + extra * p.value);
  const double relative = std::abs(value / p.value - 1);
  for (Worst& w : worst)
    if (w.property == property) {
      if (relative > w.relative) w = {property, relative, row};
      return;
    }
  worst.push_back({property, relative, row});
}

/// One property of a row: computed (SI), printed (text, in the table's unit: `unit` SI per
/// table unit) and the allowance beyond half a printed digit where the formulas differ.
struct Expected {
  const char* property;
  double computed;
  const char* printed;
  double unit;
  double extra = 0;
};

void compareAll(const std::string& row, const std::vector<Expected>& expected,
                std::vector<Worst>& worst) {
  for (const Expected& e : expected)
    compare(row, e.property, e.computed, e.printed, e.unit, e.extra, worst);
}

// ArcelorMittal Europe, "Sections and merchant bars" sales programme, tables of IPE, HE A and
// HE B (dimensions as EN 10365): A cm^2; Iy, Iz, It cm^4; Wel, Wpl cm^3, y-y the strong axis.
// A sample of 27 rows (10 HE A, 10 HE B, 7 IPE) with every property.
struct IRow {
  const char* designation;
  const char *A, *Iy, *Wely, *Wply, *Iz, *Welz, *Wplz, *It;
};
const IRow kIRows[] = {
    {"HEA100", "21.24", "349.2", "72.76", "83.01", "133.8", "26.76", "41.14", "5.24"},
    {"HEA120", "25.34", "606.2", "106.3", "119.5", "230.9", "38.48", "58.85", "5.99"},
    {"HEA140", "31.42", "1033", "155.4", "173.5", "389.3", "55.62", "84.85", "8.13"},
    {"HEA160", "38.77", "1673", "220.1", "245.1", "615.6", "76.95", "117.6", "12.19"},
    {"HEA180", "45.25", "2510", "293.6", "324.9", "924.6", "102.7", "156.5", "14.80"},
    {"HEA200", "53.83", "3692", "388.6", "429.5", "1336", "133.6", "203.8", "20.98"},
    {"HEA220", "64.34", "5410", "515.2", "568.5", "1955", "177.7", "270.6", "28.46"},
    {"HEA240", "76.84", "7763", "675.1", "744.6", "2769", "230.7", "351.7", "41.55"},
    {"HEA260", "86.82", "10450", "836.4", "919.8", "3668", "282.1", "430.2", "52.37"},
    {"HEA300", "112.5", "18260", "1260", "1383", "6310", "420.6", "641.2", "85.17"},
    {"HEB100", "26.04", "449.5", "89.91", "104.2", "167.3", "33.45", "51.42", "9.25"},
    {"HEB120", "34.01", "864.4", "144.1", "165.2", "317.5", "52.92", "80.97", "13.84"},
    {"HEB140", "42.96", "1509", "215.6", "245.4", "549.7", "78.52", "119.8", "20.06"},
    {"HEB160", "54.25", "2492", "311.5", "354.0", "889.2", "111.2", "170.0", "31.24"},
    {"HEB180", "65.25", "3831", "425.7", "481.4", "1363", "151.4", "231.0", "42.16"},
    {"HEB200", "78.08", "5696", "569.6", "642.5", "2003", "200.3", "305.8", "59.28"},
    {"HEB220", "91.04", "8091", "735.5", "827.0", "2843", "258.5", "393.9", "76.57"},
    {"HEB240", "106.0", "11260", "938.3", "1053", "3923", "326.9", "498.4", "102.7"},
    {"HEB260", "118.4", "14920", "1148", "1283", "5135", "395.0", "602.2", "123.8"},
    {"HEB300", "149.1", "25170", "1678", "1869", "8563", "570.9", "870.1", "185.0"},
    {"IPE200", "28.48", "1943", "194.3", "220.6", "142.4", "28.47", "44.61", "6.98"},
    {"IPE240", "39.12", "3892", "324.3", "366.6", "283.6", "47.27", "73.92", "12.88"},
    {"IPE270", "45.95", "5790", "428.9", "484.0", "419.9", "62.20", "96.95", "15.94"},
    {"IPE300", "53.81", "8356", "557.1", "628.4", "603.8", "80.50", "125.2", "20.12"},
    {"IPE330", "62.61", "11770", "713.1", "804.3", "788.1", "98.52", "153.7", "28.15"},
    {"IPE360", "72.73", "16270", "903.6", "1019", "1043", "122.8", "191.1", "37.32"},
    {"IPE400", "84.46", "23130", "1156", "1307", "1318", "146.4", "229.0", "51.08"},
};


// EN 10056-1 equal angles as printed in the same kind of table (3 significant digits): A cm^2,
// Iy = Iz about the axes parallel to the legs cm^4, Wel about them cm^3, Iu, Iv cm^4.
struct LRow {
  const char *designation, *A, *Iy, *Wel, *Iu, *Iv;
};
// The printed Iv lies below the outline's by more than its last digit on four of these rows,
// by up to 0.36 % (L 45x45x5: 3.25 printed, 3.2615 computed), while A, Iy, Wel and Iu agree to
// their digits; Iu + Iv = 2 Iy holds exactly for an equal angle, and the printed values miss it
// by as much, so the table's Iv is the one off. Allowed beyond half a digit: 0.25 %.
constexpr double kPrintedIvGap = 2.5e-3;
const LRow kLRows[] = {
    {"L40x40x4", "3.08", "4.47", "1.55", "7.09", "1.86"},
    {"L45x45x5", "4.30", "7.84", "2.43", "12.4", "3.25"},
    {"L50x50x5", "4.80", "11.0", "3.05", "17.4", "4.54"},
    {"L60x60x6", "6.91", "22.8", "5.29", "36.1", "9.43"},
    {"L70x70x7", "9.40", "42.3", "8.41", "67.1", "17.5"},
    {"L80x80x8", "12.3", "72.2", "12.6", "115", "29.9"},
    {"L90x90x9", "15.5", "116", "17.9", "184", "47.8"},
    {"L100x100x10", "19.2", "177", "24.6", "280", "73.0"},
};

// HE M and UPN as printed to three or four significant digits in the profile tables (EN 10365
// dimensions; UPN to DIN 1026-1): A cm^2, Iy, Iz cm^4, Wel,y, Wel,z cm^3 (a channel's Wel,z to
// the flange tips, the far side from its centroid).
struct WelRow {
  const char *designation, *A, *Iy, *Iz, *Wely, *Welz;
};
// UPN: DIN 1026-1's outline (8 % or 5 % slope, tf at b/2 from the web's back, root r1 = tf,
// toe r2 as tabulated), computed exactly, misses some printed three-digit values by more
// than half a digit: Iy, Wel,y on a few rows with either sign (UPN 50: +0.37 %, UPN 100:
// -0.32 %), Iz and Wel,z below on most (0.2 % to 0.57 %). The residual is the tables': no
// outline of the family fits them (a four-parameter least-squares fit of slope, tf's place and
// both radii still misses by 2.3 half-digits), the published tables disagree with one another
// by as much (ArcelorMittal's Wpl,y of UPN 80, 32.3 cm^3, against DIN's 2 S_x = 31.8; the
// outline 31.9), and HE M from the same tables agrees with its outline to its digits
// (docs/section_catalog.md). Allowed beyond half a digit for UPN: 0.6 %.
constexpr double kChannelOutlineGap = 6e-3;
const WelRow kWelRows[] = {
    {"HEM100", "53.2", "1143", "399", "190", "75.3"},
    {"HEM140", "80.6", "3291", "1144", "411", "157"},
    {"HEM200", "131", "10640", "3651", "967", "354"},
    {"HEM300", "303", "59200", "19400", "3480", "1250"},
    {"HEM400", "326", "104100", "19340", "4820", "1260"},
    {"UPN50", "7.12", "26.4", "9.12", "10.6", "3.75"},
    {"UPN80", "11.0", "106", "19.4", "26.5", "6.36"},
    {"UPN100", "13.5", "206", "29.3", "41.2", "8.49"},
    {"UPN120", "17.0", "364", "43.2", "60.7", "11.1"},
    {"UPN140", "20.4", "605", "62.7", "86.4", "14.8"},
    {"UPN160", "24.0", "925", "85.3", "116", "18.3"},
    {"UPN180", "28.0", "1350", "114", "150", "22.4"},
    {"UPN200", "32.2", "1910", "148", "191", "27.0"},
    {"UPN220", "37.4", "2690", "197", "245", "33.6"},
    {"UPN240", "42.3", "3600", "248", "300", "39.6"},
    {"UPN300", "58.8", "8030", "495", "535", "67.8"},
};

// UPN: DIN 1026-1:2009, Table 1, prints S_x, the first moment of half the section about the
// strong axis (cm^3, three digits), so Wpl,y = 2 S_x.
struct UpnFirstMoment {
  const char *designation, *Sx;
};
const UpnFirstMoment kUpnFirstMoments[] = {
    {"UPN80", "15.9"},  {"UPN100", "24.5"}, {"UPN120", "36.3"}, {"UPN140", "51.4"},
    {"UPN160", "68.8"}, {"UPN180", "89.6"}, {"UPN200", "114"},
};

/// A row of printed values, one per column of its table (nullptr: not compared).
struct PrintedRow {
  const char* designation;
  std::vector<const char*> printed;
};

// EN 10210-2 hot-finished square hollow sections, as tabulated from the standard's Table of
// SHS properties (amesweb.info, "Square Hollow Section Dimensions and Properties", EN 10210-2,
// three significant figures): A cm^2, I cm^4, Wel, Wpl cm^3, It cm^4. The standard's corner
// radii for calculating them: 1.5 t outside, t inside (the catalogue's).
const std::vector<PrintedRow> kShsRows = {
    {"SHS40x40x2.6", {"3.82", "8.80", "4.40", "5.31", "14.0"}},
    {"SHS40x40x5", {"6.73", "13.4", "6.68", "8.66", "22.5"}},
    {"SHS50x50x3.2", {"5.88", "21.2", "8.49", "10.2", "33.8"}},
    {"SHS50x50x6.3", {"10.6", "32.8", "13.1", "17.0", "55.2"}},
    {"SHS60x60x4", {"8.79", "45.4", "15.1", "18.3", "72.5"}},
    {"SHS60x60x8", {"16.0", "69.7", "23.2", "30.4", "118"}},
    {"SHS70x70x5", {"12.7", "88.5", "25.3", "30.8", "142"}},
    {"SHS80x80x3.2", {"9.72", "95.0", "23.7", "27.9", "148"}},
    {"SHS80x80x6.3", {"18.1", "162", "40.5", "49.7", "262"}},
    {"SHS90x90x4", {"13.6", "166", "37.0", "43.6", "260"}},
};

// EN 10219 cold-formed rectangular hollow sections (corner radii 2 t outside, t inside for
// t <= 6 mm), as tabulated by b2bmetal.eu ("Rectangular structural hollow sections - HSS of
// EN 10219, cold formed", computed with those radii; four significant figures or two
// decimals): A cm^2; Iy, Iz, It cm^4; Wel,y, Wel,z, Wpl,y, Wpl,z cm^3 (y-y across the depth h).
const std::vector<PrintedRow> kColdFormedRhsRows = {
    {"RHS40x20x2-CF", {"2.14", "4.05", "2.02", "2.61", "1.34", "1.34", "1.60", "3.45"}},
    {"RHS40x20x2.5-CF", {"2.59", "4.69", "2.35", "3.09", "1.54", "1.54", "1.88", "4.06"}},
    {"RHS40x20x3-CF", {"3.01", "5.21", "2.60", "3.50", "1.68", "1.68", "2.12", "4.57"}},
    {"RHS40x30x2-CF", {"2.54", "5.49", "2.75", "3.37", "3.51", "2.34", "2.77", "7.07"}},
    {"RHS40x30x2.5-CF", {"3.09", "6.45", "3.23", "4.03", "4.10", "2.74", "3.30", "8.47"}},
    {"RHS40x30x3-CF", {"3.61", "7.27", "3.63", "4.61", "4.60", "3.07", "3.77", "9.72"}},
    {"RHS50x30x2-CF", {"2.94", "9.54", "3.81", "4.74", "4.29", "2.86", "3.33", "9.77"}},
    {"RHS50x30x2.5-CF", {"3.59", "11.30", "4.52", "5.70", "5.05", "3.37", "3.98", "11.74"}},
    {"RHS50x30x3-CF", {"4.21", "12.83", "5.13", "6.57", "5.70", "3.80", "4.58", "13.53"}},
    {"RHS50x30x4-CF", {"5.35", "15.25", "6.10", "8.05", "6.69", "4.46", "5.58", "16.53"}},
    {"RHS60x40x2-CF", {"3.74", "18.41", "6.14", "7.47", "9.83", "4.92", "5.65", "20.70"}},
    {"RHS60x40x2.5-CF", {"4.59", "22.07", "7.36", "9.06", "11.74", "5.87", "6.84", "25.14"}},
    {"RHS60x40x3-CF", {"5.41", "25.38", "8.46", "10.53", "13.44", "6.72", "7.94", "29.28"}},
};

// Cold-formed circular hollow sections (EN 10219-2 sizes) as tabulated in a manufacturer's
// catalogue of structural tubes ("Tubes Final English", scribd document 338559492, "Circular
// Hollow Sections - Cold Formed"): A cm^2, I cm^4, Wel, Wpl cm^3, three significant figures.
const std::vector<PrintedRow> kChsRows = {
    {"CHS42.4x4", {"4.83", "8.99", "4.24", "5.92"}},
    {"CHS48.3x4", {"5.57", "13.8", "5.70", "7.87"}},
    {"CHS48.3x5", {"6.8", "16.2", "6.69", "9.42"}},
    {"CHS60.3x4", {"7.07", "28.2", "9.34", "12.7"}},
    {"CHS60.3x5", {"8.69", "33.5", "11.10", "15.3"}},
    {"CHS76.1x4", {"9.06", "59.1", "15.5", "20.8"}},
    {"CHS76.1x5", {"11.2", "70.9", "18.6", "25.3"}},
    {"CHS76.1x6.3", {"13.8", "84.8", "22.3", "30.8"}},
    {"CHS88.9x4", {"10.7", "96.3", "21.7", "28.9"}},
    {"CHS88.9x5", {"13.2", "116", "26.2", "35.2"}},
    {"CHS88.9x6.3", {"16.3", "140", "31.5", "43.1"}},
};


// The US shapes: AISC Shapes Database v15.0 as printed in the Steel Construction Manual, 15th
// ed. (Tables 1-1, 1-11, 1-12, 1-13), three significant figures: A in^2, Ix, Iy, J in^4,
// Zx in^3 (x-x the strong axis: the catalogue's y-y). Read from the same extract as the
// catalogue's dimensions (problems/deck/catalog/tables/W.csv, HSS.csv, HSS_round.csv).
struct UsRow {
  const char *designation, *A, *Ix, *Iy, *Zx, *J;
};
const UsRow kWRows[] = {
    {"W36X150", "44.3", "9040", "270", "581", "10.1"},
    {"W33X118", "34.7", "5900", "187", "415", "5.30"},
    {"W30X99", "29.0", "3990", "128", "312", "3.77"},
    {"W27X94", "27.6", "3270", "124", "278", "4.03"},
    {"W24X76", "22.4", "2100", "82.5", "200", "2.68"},
    {"W24X55", "16.2", "1350", "29.1", "134", "1.18"},
    {"W21X62", "18.3", "1330", "57.5", "144", "1.83"},
    {"W21X44", "13.0", "843", "20.7", "95.4", "0.770"},
    {"W18X50", "14.7", "800", "40.1", "101", "1.24"},
    {"W18X35", "10.3", "510", "15.3", "66.5", "0.506"},
    {"W16X40", "11.8", "518", "28.9", "73.0", "0.794"},
    {"W16X26", "7.68", "301", "9.59", "44.2", "0.262"},
    {"W14X132", "38.8", "1530", "548", "234", "12.3"},
    {"W14X90", "26.5", "999", "362", "157", "4.06"},
    {"W14X68", "20.0", "722", "121", "115", "3.01"},
    {"W14X48", "14.1", "484", "51.4", "78.4", "1.45"},
    {"W14X22", "6.49", "199", "7.00", "33.2", "0.208"},
    {"W12X65", "19.1", "533", "174", "96.8", "2.18"},
    {"W12X40", "11.7", "307", "44.1", "57.0", "0.906"},
    {"W12X26", "7.65", "204", "17.3", "37.2", "0.300"},
    {"W10X49", "14.4", "272", "93.4", "60.4", "1.39"},
    {"W10X33", "9.71", "171", "36.6", "38.8", "0.583"},
    {"W10X12", "3.54", "53.8", "2.18", "12.6", "0.0547"},
    {"W8X31", "9.13", "110", "37.1", "30.4", "0.536"},
    {"W8X18", "5.26", "61.9", "7.97", "17.0", "0.172"},
    {"W8X10", "2.96", "30.8", "2.09", "8.87", "0.0426"},
};
const UsRow kHssRows[] = {
    {"HSS24X12X1/2", "32.1", "2420", "829", "248", "1980"},
    {"HSS22X22X3/4", "58.2", "4350", "4350", "462", "6860"},
    {"HSS20X12X1/2", "28.3", "1550", "705", "188", "1540"},
    {"HSS18X6X3/8", "16.0", "602", "106", "86.4", "302"},
    {"HSS16X16X1/2", "28.3", "1130", "1130", "164", "1770"},
    {"HSS8X4X1/2", "9.74", "71.8", "23.6", "23.5", "61.1"},
    {"HSS7X7X1/2", "11.6", "80.5", "80.5", "27.9", "133"},
    {"HSS7X5X5/16", "6.43", "43.0", "25.5", "15.0", "52.1"},
    {"HSS6X6X3/8", "7.58", "39.5", "39.5", "15.8", "64.6"},
    {"HSS6X4X3/8", "6.18", "28.3", "14.9", "11.9", "32.8"},
    {"HSS5X5X1/4", "4.30", "16.0", "16.0", "7.61", "25.8"},
    {"HSS4X4X1/4", "3.37", "7.80", "7.80", "4.69", "12.8"},
    {"HSS4X2X3/16", "1.89", "3.66", "1.22", "2.34", "3.08"},
};
struct RoundRow {
  const char *designation, *A, *I, *Z, *J;
};
const RoundRow kRoundRows[] = {
    {"HSS20.000X0.500", "28.5", "1360", "177", "2720"},
    {"HSS16.000X0.375", "17.2", "526", "85.5", "1050"},
    {"HSS12.750X0.500", "17.9", "339", "70.2", "678"},
    {"HSS10.750X0.250", "7.70", "106", "25.8", "213"},
    {"HSS8.625X0.322", "7.85", "68.1", "20.8", "136"},
    {"HSS6.625X0.280", "5.20", "26.4", "10.5", "52.7"},
    {"HSS6.000X0.500", "8.09", "31.2", "14.3", "62.4"},
    {"HSS5.563X0.258", "4.01", "14.2", "6.80", "28.5"},
    {"HSS4.500X0.237", "2.96", "6.79", "4.03", "13.6"},
    {"HSS3.500X0.300", "2.82", "3.69", "2.90", "7.38"},
};

constexpr double kInch = 0.0254;
constexpr double kIn2 = kInch * kInch, kIn3 = kIn2 * kInch, kIn4 = kIn2 * kIn2;

// AISC's names for the catalogue's properties (its x-x is the catalogue's y-y).
double usA(const CatalogProperties& p) { return p.A; }
double usIx(const CatalogProperties& p) { return p.Iy; }
double usIy(const CatalogProperties& p) { return p.Iz; }
double usZx(const CatalogProperties& p) { return p.Wply; }
double usJ(const CatalogProperties& p) { return p.It; }

/// How far a property can move when each printed dimension of the row moves by half a unit of
/// its last printed digit (to first order, the sum of the moves one at a time): the printed
/// properties are computed from unrounded dimensions, so a computed one may differ from them
/// by this much on top of their own rounding. `halfUnit` gives a dimension's half unit.
template <class Property, class HalfUnit>
double roundingSpread(const CatalogEntry& e, Property property, HalfUnit halfUnit) {
  const double base = property(catalogProperties(e));
  double spread = 0;
  for (const auto& [key, value] : e.dims) {
    const double h = halfUnit(key, value);
    if (h == 0) continue;
    CatalogEntry moved = e;
    moved.dims[key] = value + h;
    spread += std::abs(property(catalogProperties(moved)) - base);
  }
  return spread;
}

/// Half a unit of the third significant figure (the W table's d, bf, tw, tf, kdes).
double thirdFigure(const std::string&, double value) {
  return 0.5 * std::pow(10.0, std::floor(std::log10(std::abs(value))) - 2);
}

/// HSS: the outside dimensions are the designation's, exact; t_des is printed to 0.001 in.
double wallOnly(const std::string& key, double) { return key == "t_des" ? 5e-4 : 0; }

/// Each property of a US row against its printed value: half a unit of the printed digit,
/// plus the spread of the printed dimensions' rounding, plus `extra` (relative) where the
/// formulas differ (J).
void compareUs(const CatalogEntry& e, const std::string& property,
               double (*get)(const CatalogProperties&), const char* printed, double unit,
               double (*halfUnit)(const std::string&, double), double extra,
               std::vector<Worst>& worst) {
  const double spread = roundingSpread(e, get, halfUnit) / unit;
  const double value = std::stod(printed);
  compare(e.designation, property, get(catalogProperties(e)), printed, unit,
          spread / value + extra, worst);
}

const CatalogEntry& entry(const std::string& designation) {
  const CatalogEntry* e = findCatalogEntry(designation);
  REQUIRE_MESSAGE(e != nullptr, designation);
  return *e;
}

void report(const std::string& family, const std::vector<Worst>& worst) {
  std::string line = family + ": largest |computed / printed - 1|:";
  for (const Worst& w : worst) line += " " + w.property + " " + std::to_string(w.relative) + " (" + w.row + ")";
  MESSAGE(line);
}

/// A column of a printed table: the property's name there, how to read it from the
/// catalogue's properties, and the table's unit (SI per cm^k).
struct Column {
  const char* name;
  double (*get)(const CatalogProperties&);
  double unit;
};
const Column kColA{"A", [](const CatalogProperties& p) { return p.A; }, 1e-4};
const Column kColIy{"Iy", [](const CatalogProperties& p) { return p.Iy; }, 1e-8};
const Column kColIz{"Iz", [](const CatalogProperties& p) { return p.Iz; }, 1e-8};
const Column kColWely{"Wel,y", [](const CatalogProperties& p) { return p.Wely; }, 1e-6};
const Column kColWelz{"Wel,z", [](const CatalogProperties& p) { return p.Welz; }, 1e-6};
const Column kColWply{"Wpl,y", [](const CatalogProperties& p) { return p.Wply; }, 1e-6};
const Column kColWplz{"Wpl,z", [](const CatalogProperties& p) { return p.Wplz; }, 1e-6};
const Column kColIt{"It", [](const CatalogProperties& p) { return p.It; }, 1e-8};
const Column kColIu{"Iu", [](const CatalogProperties& p) { return p.Iu; }, 1e-8};
const Column kColIv{"Iv", [](const CatalogProperties& p) { return p.Iv; }, 1e-8};

/// Every printed value of the rows against the computed one, to half its last digit; the
/// largest relative differences reported under `family`.
void compareRows(const std::string& family, const std::vector<Column>& columns,
                 const std::vector<PrintedRow>& rows) {
  std::vector<Worst> worst;
  for (const PrintedRow& r : rows) {
    REQUIRE(r.printed.size() == columns.size());
    const CatalogProperties p = catalogProperties(entry(r.designation));
    std::vector<Expected> expected;
    for (std::size_t i = 0; i < columns.size(); ++i)
      if (r.printed[i] != nullptr)
        expected.push_back({columns[i].name, columns[i].get(p), r.printed[i], columns[i].unit});
    compareAll(r.designation, expected, worst);
  }
  report(family, worst);
}

// A spandrel: the corner square r x r less the quarter disc that rounds it, its square's
// inner edge at distance c from the axis and the corner at c + r. Its integrals of |y|^k dA
// about the axis (k = 0, 1, 2), the quarter disc's by integrating (c + rho cos t)^k rho.
double spandrel(double r, double c, int k) {
  const double pi = std::numbers::pi;
  const double square = r * (std::pow(c + r, k + 1) - std::pow(c, k + 1)) / (k + 1);
  const double quarter = k == 0   ? pi * r * r / 4
                         : k == 1 ? c * pi * r * r / 4 + r * r * r / 3
                                  : c * c * pi * r * r / 4 + 2 * c * r * r * r / 3 +
                                        pi * std::pow(r, 4) / 16;
  return square - quarter;
}

/// A rectangle H x B less its four rounded corners (radius r): area (k = 0), half its
/// plastic modulus (k = 1, the first moment of the upper half) or its second moment (k = 2)
/// about the axis across H.
double roundedRectangle(double H, double B, double r, int k) {
  const double whole = k == 0 ? B * H : k == 1 ? B * H * H / 8 : B * H * H * H / 12;
  const int corners = k == 1 ? 2 : 4;  // the upper half holds two
  return whole - corners * spandrel(r, H / 2 - r, k);
}

// A column of IPE 300 from the catalogue, clamped at its foot, pushed at its head: in the
// frame's plane (global x, across the web: the strong axis) and, in 3D, out of it (global z,
// along the flanges: the weak axis). Euler-Bernoulli elements are exact for a tip load:
// u = P L^3 / (3 E I).
std::string column(bool threeD, const std::string& load, const std::string& measured,
                   const std::string& I) {
  const std::string z = threeD ? ", 0" : "";
  return std::string(threeD ? "model: {dimension: 3d}\n" : "") + R"(
materials:
  - {name: steel, E: 210 GPa, nu: 0.3, rho: 7850}
sections:
  - {name: col, catalog: IPE300}
parameters: {L: 4 m, P: 10 kN}
nodes:
  - {name: foot, at: [0, 0)" + z + R"(]}
  - {name: head, at: [0, L)" + z + R"(]}
members:
  - {name: column, from: foot, to: head, section: col, elements: 4}
supports:
  - {name: base, at: foot, fix: clamped}
loads:
  - {type: point, at: head, )" + load + R"(: P}
checks:
  - {name: sway, quantity: displacement head )" + measured + R"(,
     reference: P * L^3 / (3 * 210 GPa * )" + I + R"(), tolerance: 1e-4}
)";
}

double tipDeflection(const std::string& deck) {
  const Study study = test::solveDeckText(deck, "column.yaml");
  REQUIRE(study.run);
  REQUIRE(study.run->checks.size() == 1);
  CHECK(study.run->checks.front().pass());
  return study.run->checks.front().computed;
}

}  // namespace

TEST_SUITE("section catalogue") {
  TEST_CASE("an IPE 300 column bends about its strong axis in the plane, its weak one across") {
    // The printed Iy 8356 cm^4 and Iz 603.8 cm^4 (ArcelorMittal) are the exact outline's to
    // half a unit of their last digit: 6.0e-5 and 8.3e-5 of them; 1e-4 allows for that.
    const double E = 210e9, L = 4, P = 10e3;
    const double strong = P * L * L * L / (3 * E * 8356e-8);
    CHECK(test::relError(tipDeflection(column(true, "fx", "ux", "8356 cm^4")), strong) < 1e-4);
    CHECK(test::relError(tipDeflection(column(true, "fz", "uz", "603.8 cm^4")), P * L * L * L / (3 * E * 603.8e-8)) <
          1e-4);
    // The same column in a planar frame bends the strong way.
    CHECK(test::relError(tipDeflection(column(false, "fx", "ux", "8356 cm^4")), strong) < 1e-4);
  }

  TEST_CASE("a parameter picks the designation from a list, as a sweep would") {
    // problems/steel_column.yaml picks HEB200 (size 2); size 3 is HEB240. Its sway across the
    // web is Hy h^3 / (3 E Iy), exact for its elements: the two runs' ratio is the inverse
    // ratio of the catalogue's Iy, to round-off.
    const std::string text = test::fileContents(test::problemsDir() / "steel_column.yaml");
    std::string bigger = text;
    bigger.replace(bigger.find("size: 2 "), 8, "size: 3 ");
    const Study two = test::solveDeckText(text, "steel_column.yaml");
    const Study three = test::solveDeckText(bigger, "steel_column.yaml");
    REQUIRE(two.run);
    REQUIRE(three.run);
    REQUIRE(two.run->catalogSections.size() == 1);
    REQUIRE(three.run->catalogSections.size() == 1);
    CHECK(two.run->catalogSections[0].designation == "HEB200");
    CHECK(three.run->catalogSections[0].designation == "HEB240");
    const double ratio = three.run->checks[0].computed / two.run->checks[0].computed;
    CHECK(test::relError(ratio, two.run->catalogSections[0].properties.Iy /
                                    three.run->catalogSections[0].properties.Iy) < 1e-10);
    std::string outside = text;
    outside.replace(outside.find("size: 2 "), 8, "size: 4 ");
    CHECK_THROWS_WITH_AS(test::solveDeckText(outside, "steel_column.yaml"),
                         doctest::Contains("sections[0].pick"), DeckError);
  }

  TEST_CASE("an unknown designation: exit 2 at its line, the nearest row suggested") {
    const auto dir = test::scratchDir("catalog_unknown");
    const auto deck = dir / "typo.yaml";
    std::ofstream(deck) << R"(materials:
  - {name: steel, E: 210 GPa, nu: 0.3}
sections:
  - {name: beam, catalog: HEB 2O0}
segments:
  - {length: 3, section: beam, elements: 2}
supports:
  - {name: root, at: start, fix: clamped}
)";
    const test::ProcessResult r = test::runBeamrotor({"check", deck.string()});
    CAPTURE(r.err);
    CHECK(r.exitCode == 2);
    CHECK(r.err.find(deck.string() + ":4:") != std::string::npos);
    CHECK(r.err.find("sections[0].catalog") != std::string::npos);
    CHECK(r.err.find("no section 'HEB 2O0' in the catalogue; did you mean 'HEB200'?") !=
          std::string::npos);
  }

  TEST_CASE("the tables hold every family, with the rows' dimensions read") {
    std::map<std::string, int> rows;
    for (const CatalogEntry& e : sectionCatalog()) ++rows[e.family];
    std::string counts;
    for (const auto& [family, n] : rows) counts += family + " " + std::to_string(n) + ", ";
    MESSAGE("rows per family: " << counts);
    CHECK(rows["IPE"] == 18);  // IPE 80 to 600
    CHECK(rows["HEA"] == 24);  // HE 100 to 1000
    CHECK(rows["HEB"] == 24);
    CHECK(rows["HEM"] == 24);
    CHECK(rows["UPN"] == 18);  // UPN 50 to 400
    CHECK(rows["L"] > 40);
    CHECK(rows["CHS"] > 70);
    CHECK(rows["RHS"] > 100);
    CHECK(rows["SHS"] > 150);
    CHECK(rows["W"] == 26);  // W8X10 to W36X150, a subset
    CHECK(rows["HSS"] == 13);
    CHECK(rows["HSS_round"] == 10);
    const CatalogEntry& w = entry("w14x90");
    CHECK(w.designation == "W14X90");
    CHECK(w.dim("kdes") == 1.31);
    CHECK(w.metres("d") == doctest::Approx(14.0 * 0.0254).epsilon(1e-15));  // read in inches
    CHECK(w.unit == findUnit("in")->si);  // the deck's inch
    CHECK(entry("IPE300").unit == findUnit("mm")->si);
    CHECK(entry("HSS6.625X0.280").dim("t_des") == 0.26);
    const CatalogEntry& ipe = entry("IPE 300");
    CHECK(ipe.dim("h") == 300);
    CHECK(ipe.dim("tf") == 10.7);
    CHECK(entry("HE 300 B").designation == "HEB300");
    CHECK(entry("shs100x100x5-cf").dim("r_out") == 10);  // 2 t for t <= 6 mm (EN 10219-2)
  }

  TEST_CASE("I and H sections against the printed A, I, Wel, Wpl and It (27 rows)") {
    std::map<std::string, std::vector<Worst>> byFamily;
    for (const IRow& r : kIRows) {
      const CatalogEntry& e = entry(r.designation);
      std::vector<Worst>& worst = byFamily[e.family];
      const CatalogProperties p = catalogProperties(e);
      compareAll(r.designation,
                 {{"A", p.A, r.A, 1e-4},
                  {"Iy", p.Iy, r.Iy, 1e-8},
                  {"Iz", p.Iz, r.Iz, 1e-8},
                  {"Wel,y", p.Wely, r.Wely, 1e-6},
                  {"Wel,z", p.Welz, r.Welz, 1e-6},
                  {"Wpl,y", p.Wply, r.Wply, 1e-6},
                  {"Wpl,z", p.Wplz, r.Wplz, 1e-6},
                  {"It", p.It, r.It, 1e-8}},
                 worst);
    }
    for (const auto& [family, worst] : byFamily) report(family, worst);
  }

  TEST_CASE("HE M and UPN against the printed A, I and Wel (5 and 11 rows)") {
    std::map<std::string, std::vector<Worst>> byFamily;
    for (const WelRow& r : kWelRows) {
      const CatalogEntry& e = entry(r.designation);
      const CatalogProperties p = catalogProperties(e);
      const double gap = e.family == "UPN" ? kChannelOutlineGap : 0;
      compareAll(r.designation,
                 {{"A", p.A, r.A, 1e-4, gap},
                  {"Iy", p.Iy, r.Iy, 1e-8, gap},
                  {"Iz", p.Iz, r.Iz, 1e-8, gap},
                  {"Wel,y", p.Wely, r.Wely, 1e-6, gap},
                  {"Wel,z", p.Welz, r.Welz, 1e-6, gap}},
                 byFamily[e.family]);
    }
    for (const auto& [family, worst] : byFamily) report(family, worst);
  }

  TEST_CASE("UPN: the plastic modulus against DIN 1026-1's first moment of half the section") {
    // Same outline gap as A, I and Wel above (kChannelOutlineGap); measured: up to 0.31 %
    // (UPN 80: 2 x 15.95 cm^3 computed against 2 x 15.9).
    std::vector<Worst> worst;
    for (const UpnFirstMoment& r : kUpnFirstMoments) {
      const CatalogProperties p = catalogProperties(entry(r.designation));
      compareAll(r.designation, {{"Sx = Wpl,y / 2", p.Wply / 2, r.Sx, 1e-6, kChannelOutlineGap}},
                 worst);
    }
    report("UPN", worst);
  }

  TEST_CASE("hot-finished SHS against EN 10210-2's printed A, I, Wel, Wpl and It (10 rows)") {
    // Every value within half a unit of its last printed digit, It included: the catalogue's
    // It is the standard's own closed-cell formula (StandardSections.cpp).
    compareRows("SHS (EN 10210)", {kColA, kColIy, kColWely, kColWply, kColIt}, kShsRows);
  }

  TEST_CASE("cold-formed RHS against EN 10219's printed A, I, Wel, Wpl and It (13 rows)") {
    // Within half a unit of the last printed digit on every property: the corner radii
    // (2 t, t) and the closed-cell It are the standard's.
    compareRows("RHS (EN 10219)",
                {kColA, kColIy, kColWely, kColWply, kColIz, kColWelz, kColWplz, kColIt},
                kColdFormedRhsRows);
  }

  TEST_CASE("cold-formed CHS against the printed A, I, Wel and Wpl (11 rows)") {
    compareRows("CHS", {kColA, kColIy, kColWely, kColWply}, kChsRows);
  }

  TEST_CASE("equal angles against the printed A, I about the legs, Wel, Iu and Iv (8 rows)") {
    std::vector<Worst> worst;
    for (const LRow& r : kLRows) {
      const CatalogProperties p = catalogProperties(entry(r.designation));
      compareAll(r.designation,
                 {{"A", p.A, r.A, 1e-4},
                  {"Iy", p.Iy, r.Iy, 1e-8},
                  {"Iz", p.Iz, r.Iy, 1e-8},
                  {"Wel", p.Wely, r.Wel, 1e-6},
                  {"Iu", p.Iu, r.Iu, 1e-8},
                  {"Iv", p.Iv, r.Iv, 1e-8, kPrintedIvGap}},
                 worst);
    }
    report("L", worst);
  }

  TEST_CASE("unequal angles: the printed area and centroid (6 rows)") {
    // A profile table of EN 10056-1 angles printing A (mm^2, four digits) and the centroid's
    // distances from the backs of the legs (mm): e across the long leg (from its back, along the
    // short leg) and along it. They fix the rows' root and toe radii (r2 = r1 / 2): one
    // millimetre of r1 moves A by 2 to 4 mm^2 here, beyond the printed digit. Left out: the
    // table's L 100x50x8, whose A (1141 mm^2, r1 = 7) contradicts its own centroid (11.25 and
    // 35.9 mm) and the 8.99 kg/m of mass tables, both of which r1 = 9 meets (the catalogue's).
    struct URow {
      const char *designation, *A, *eShort, *eLong;
    };
    const URow rows[] = {
        {"L50x30x5", "378", "7.41", "17.27"},     {"L60x40x6", "568", "10.11", "19.98"},
        {"L80x40x8", "901", "9.63", "29.4"},      {"L100x65x7", "1117", "15.12", "32.3"},
        {"L150x100x10", "2418", "23.36", "48"},
        {"L200x100x10", "2924", "20.13", "69.3"},
    };
    std::vector<Worst> worst;
    for (const URow& r : rows) {
      const CatalogEntry& e = entry(r.designation);
      const auto d = [&](const char* k) { return e.dim(k) * 1e-3; };
      // The heel at the origin, the leg h (the long one) along y: the centroid's y is its
      // distance along the long leg, z across it.
      const OutlineProperties o =
          outlineProperties(angleOutline(d("h"), d("b"), d("t"), d("r"), d("r_toe")));
      compareAll(r.designation,
                 {{"A", catalogProperties(e).A, r.A, 1e-6},
                  {"e across the long leg", o.cz, r.eShort, 1e-3},
                  {"e along the long leg", o.cy, r.eLong, 1e-3}},
                 worst);
    }
    report("L unequal", worst);
  }

  TEST_CASE("unequal angles against the printed A, I, Wel, Iu and Iv (10 rows)") {
    // EN 10056-1 unequal angles as tabulated with their properties by eng-calculations.com
    // ("Dimensions and sectional properties of hot-rolled unequal leg angles"; two decimals or
    // three figures): A cm^2; Iy (bending the long leg h), Iz, Iu, Iv cm^4; Wel,y, Wel,z cm^3
    // to the toes. L 45x30x4's printed Iu and Iv (6.65, 1.18) are left out: they miss the
    // outline's (6.637, 1.193) by 0.2 % and 1.1 % while its A, Iy, Iz and Wel agree and no
    // radius reproduces them (r2 = 2.25 or 0 moves them the other way or not enough).
    const std::vector<PrintedRow> rows{
        {"L30x20x3", {"1.43", "1.25", "0.62", "0.44", "0.29", "1.43", "0.26"}},
        {"L30x20x4", {"1.86", "1.59", "0.81", "0.55", "0.38", "1.81", "0.33"}},
        {"L40x20x4", {"2.26", "3.59", "1.42", "0.60", "0.39", "3.80", "0.39"}},
        {"L40x25x4", {"2.46", "3.89", "1.47", "1.16", "0.62", "4.35", "0.70"}},
        {"L45x30x4", {"2.87", "5.78", "1.91", "2.05", "0.91", nullptr, nullptr}},
        {"L50x30x5", {"3.78", "9.36", "2.86", "2.51", "1.11", "10.3", "1.54"}},
        {"L60x30x5", {"4.28", "15.6", "4.07", "2.63", "1.14", "16.5", "1.71"}},
        {"L60x40x5", {"4.79", "17.2", "4.25", "6.11", "2.02", "19.7", "3.54"}},
        {"L60x40x6", {"5.68", "20.1", "5.03", "7.12", "2.38", "23.1", "4.16"}},
        {"L65x50x5", {"5.54", "23.2", "5.14", "11.9", "3.19", "28.8", "6.32"}},
    };
    compareRows("L unequal", {kColA, kColIy, kColWely, kColIz, kColWelz, kColIu, kColIv}, rows);
  }

  TEST_CASE("angles: It against the SCI Blue Book's printed torsion constant (34 + 17 rows)") {
    // SCI P363 ("Blue Book", Steel building design: design data), BS EN 10056-1 equal and
    // unequal angles, three significant figures, cm^4; as transcribed in the steelsnakes
    // package (github.com/waynemaranga/steelsnakes, UK/data/L_EQUAL.json and
    // data/sections/UK/L_UNEQUAL.json), whose other columns (A, I, Iu, Iv, Wel) are the tables'
    // tested above (the values as transcribed: "0.24" where the book may print "0.240" is taken
    // to its two digits). The printed It is not the St Venant constant of the outline: that constant
    // (the stress function, tests/fem/model/test_open_section_torsion.cpp) lies 1.6 % to 3.6 %
    // below every printed value. Our formula (Roark's L with the rounded toes) lies from -1.3 %
    // (L 200x200x24) to +2.7 % (L 30x30x3) of them, measured; allowed 3 % beyond half a digit.
    // L 100x50x8 is left out (the Blue Book's r1 = 8 mm, the catalogue's 9, docs).
    constexpr double kPrintedAngleTorsionGap = 3e-2;
    const std::pair<const char*, const char*> rows[] = {
        {"L20x20x3", "0.038"},    {"L25x25x3", "0.047"},     {"L25x25x4", "0.107"},
        {"L30x30x3", "0.061"},    {"L30x30x4", "0.137"},     {"L35x35x4", "0.158"},
        {"L40x40x4", "0.188"},    {"L40x40x5", "0.352"},     {"L50x50x4", "0.24"},
        {"L50x50x5", "0.45"},    {"L50x50x6", "0.755"},     {"L60x60x5", "0.550"},
        {"L60x60x6", "0.922"},    {"L60x60x8", "2.09"},      {"L70x70x6", "1.09"},
        {"L70x70x7", "1.69"},     {"L75x75x6", "1.17"},      {"L75x75x8", "2.65"},
        {"L80x80x8", "2.88"},     {"L80x80x10", "5.45"},     {"L90x90x7", "2.24"},
        {"L90x90x8", "3.28"},     {"L90x90x10", "6.2"},     {"L100x100x8", "3.68"},
        {"L100x100x10", "6.97"},  {"L100x100x12", "11.8"},   {"L120x120x10", "8.41"},
        {"L120x120x12", "14.2"},  {"L150x150x10", "10.8"},   {"L150x150x12", "18.2"},
        {"L150x150x15", "34.6"},  {"L200x200x16", "56.1"},   {"L200x200x20", "107"},
        {"L200x200x24", "182"},   {"L30x20x3", "0.049"},     {"L30x20x4", "0.11"},
        {"L40x20x4", "0.131"},    {"L40x25x4", "0.142"},     {"L45x30x4", "0.166"},
        {"L50x30x5", "0.34"},    {"L60x30x5", "0.382"},     {"L60x40x5", "0.435"},
        {"L60x40x6", "0.735"},    {"L65x50x5", "0.498"},     {"L75x50x6", "0.935"},
        {"L80x40x8", "2.05"},     {"L100x65x7", "2.02"},     {"L100x75x8", "3.13"},
        {"L150x90x10", "8.3"},   {"L200x100x10", "10.7"},   {"L200x150x12", "20.9"}};
    std::vector<Worst> worst;
    for (const auto& [designation, It] : rows) {
      const CatalogProperties p = catalogProperties(entry(designation));
      compareAll(designation, {{"It", p.It, It, 1e-8, kPrintedAngleTorsionGap}}, worst);
    }
    report("L (It, SCI Blue Book)", worst);
  }

  TEST_CASE("every hollow section against the closed forms of its rounded corners") {
    // A, I and Wpl of an RHS are a rounded rectangle less its rounded hole: exact in closed
    // form, so they agree with the outline's Green's-theorem integrals and polygon clipping to
    // round-off (1e-9 relative allows for the plastic modulus' 512-chord arcs). A CHS: the
    // ring's A = pi (D^2 - d^2) / 4, I = pi (D^4 - d^4) / 64, Wpl = (D^3 - d^3) / 6.
    int checked = 0;
    for (const CatalogEntry& e : sectionCatalog()) {
      CAPTURE(e.designation);
      const CatalogProperties p = catalogProperties(e);
      if (e.shape == CatalogShape::rectangularHollow) {
        // The US HSS rows print H, B and t_des; AISC's corner radii are 2 t_des and t_des.
        const bool us = e.dims.contains("t_des");
        const double t = us ? e.metres("t_des") : e.metres("t");
        const double H = e.metres(us ? "H" : "h"), B = e.metres(us ? "B" : "b");
        const double ro = us ? 2 * t : e.metres("r_out"), ri = us ? t : e.metres("r_in");
        const auto tube = [&](double h, double b, int k) {
          return roundedRectangle(h, b, ro, k) - roundedRectangle(h - 2 * t, b - 2 * t, ri, k);
        };
        const auto across = [&](double h, double b, int k) {  // bending about the other axis
          return roundedRectangle(b, h, ro, k) - roundedRectangle(b - 2 * t, h - 2 * t, ri, k);
        };
        CHECK(test::relError(p.A, tube(H, B, 0)) < 1e-12);
        CHECK(test::relError(p.Iy, tube(H, B, 2)) < 1e-12);
        CHECK(test::relError(p.Iz, across(H, B, 2)) < 1e-12);
        CHECK(test::relError(p.Wely, tube(H, B, 2) / (H / 2)) < 1e-12);
        CHECK(test::relError(p.Wply, 2 * tube(H, B, 1)) < 1e-9);
        CHECK(test::relError(p.Wplz, 2 * across(H, B, 1)) < 1e-9);
        ++checked;
      }
      if (e.shape == CatalogShape::circularHollow) {
        const bool us = e.dims.contains("t_des");
        const double D = e.metres(us ? "OD" : "D"), d = D - 2 * e.metres(us ? "t_des" : "t");
        const double pi = std::numbers::pi;
        CHECK(test::relError(p.A, pi * (D * D - d * d) / 4) < 1e-12);
        CHECK(test::relError(p.Iy, pi * (std::pow(D, 4) - std::pow(d, 4)) / 64) < 1e-12);
        CHECK(test::relError(p.Wply, (D * D * D - d * d * d) / 6) < 1e-12);
        CHECK(test::relError(p.It, 2 * p.Iy) < 1e-12);
        ++checked;
      }
    }
    CHECK(checked > 300);
  }

  TEST_CASE("US W shapes against AISC's printed A, Ix, Iy, Zx and J (26 rows)") {
    // AISC prints the dimensions to three figures but computes its properties from unrounded
    // ones: a row's tolerance is half a printed digit of the property plus the spread of the
    // dimensions' rounding (roundingSpread: 0.1 % to 0.6 % of A). J: AISC's formula for W
    // shapes (flange and web plates with the fillets' junction term, its own constants) is
    // not ours (the European tables' formula, StandardSections.cpp); the
    // measured gap is reported below and allowed as kWTorsionGap.
    constexpr double kWTorsionGap = 0.09;  // measured: up to 7.7 % (W10X12), thin rows most
    // The area: W30X99's printed A (29.0 in^2) lies 0.62 % below the area of its printed
    // dimensions, 0.03 % beyond their rounding spread; its printed weight says otherwise
    // (99 lb/ft at 490 lb/ft^3 is 29.1 in^2). Allowed beyond the spread for A: 0.1 %.
    constexpr double kWAreaGap = 1e-3;
    std::vector<Worst> worst;
    for (const UsRow& r : kWRows) {
      const CatalogEntry& e = entry(r.designation);
      compareUs(e, "A", usA, r.A, kIn2, thirdFigure, kWAreaGap, worst);
      compareUs(e, "Ix", usIx, r.Ix, kIn4, thirdFigure, 0, worst);
      compareUs(e, "Iy", usIy, r.Iy, kIn4, thirdFigure, 0, worst);
      compareUs(e, "Zx", usZx, r.Zx, kIn3, thirdFigure, 0, worst);
      compareUs(e, "J", usJ, r.J, kIn4, thirdFigure, kWTorsionGap, worst);
    }
    report("W", worst);
  }

  TEST_CASE("US HSS against AISC's printed A, Ix, Iy, Zx and J (13 rectangular, 10 round)") {
    // The outside dimensions are the designation's; t_des is printed to 0.001 in (its spread
    // is in the tolerance as for W). Round HSS: the ring's closed forms, J = 2 I as AISC
    // takes it. Rectangular HSS: AISC's J is its thin-walled formula for a rounded tube, ours
    // (StandardSections.cpp) another; the measured gap is reported and allowed as
    // kHssTorsionGap.
    constexpr double kHssTorsionGap = 0.015;  // measured: up to 1.07 % (HSS8X4X1/2)
    std::vector<Worst> worst;
    for (const UsRow& r : kHssRows) {
      const CatalogEntry& e = entry(r.designation);
      compareUs(e, "A", usA, r.A, kIn2, wallOnly, 0, worst);
      compareUs(e, "Ix", usIx, r.Ix, kIn4, wallOnly, 0, worst);
      compareUs(e, "Iy", usIy, r.Iy, kIn4, wallOnly, 0, worst);
      compareUs(e, "Zx", usZx, r.Zx, kIn3, wallOnly, 0, worst);
      compareUs(e, "J", usJ, r.J, kIn4, wallOnly, kHssTorsionGap, worst);
    }
    report("HSS", worst);
    std::vector<Worst> round;
    for (const RoundRow& r : kRoundRows) {
      const CatalogEntry& e = entry(r.designation);
      compareUs(e, "A", usA, r.A, kIn2, wallOnly, 0, round);
      compareUs(e, "I", usIx, r.I, kIn4, wallOnly, 0, round);
      compareUs(e, "Z", usZx, r.Z, kIn3, wallOnly, 0, round);
      compareUs(e, "J", usJ, r.J, kIn4, wallOnly, 0, round);
    }
    report("HSS round", round);
  }
}
