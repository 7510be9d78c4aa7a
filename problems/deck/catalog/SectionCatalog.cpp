#include "problems/deck/catalog/SectionCatalog.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>

#include "fem/model/BendingModuli.hpp"
#include "fem/model/StandardSections.hpp"
#include "problems/deck/catalog/CatalogTables.hpp"

namespace beamrotor {

namespace {

CatalogShape shapeOf(std::string_view family) {
  if (family == "UPN") return CatalogShape::channel;
  if (family == "L") return CatalogShape::angle;
  if (family == "CHS" || family == "HSS_round") return CatalogShape::circularHollow;
  if (family == "RHS" || family == "SHS" || family == "HSS") return CatalogShape::rectangularHollow;
  return CatalogShape::iSection;  // IPE, HEA, HEB, HEM, W
}

std::vector<std::string> splitCommas(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream in(line);
  for (std::string cell; std::getline(in, cell, ',');) cells.push_back(cell);
  return cells;
}

/// A table's length unit in metres. The sizes are the deck's units table's
/// (problems/deck/parse/Units.cpp, which the catalogue may not include; the tests compare).
double tableUnit(const CatalogTable& table, const std::string& name) {
  if (name == "mm") return 1e-3;
  if (name == "cm") return 1e-2;
  if (name == "m") return 1;
  if (name == "in") return 0.0254;
  throw std::logic_error("catalogue table " + std::string(table.family) + ": unit '" + name +
                         "' is not a length unit of the catalogue");
}

/// The rows of one table: comment lines start with '#', the first other line names the
/// columns, the first column is the designation and the numeric columns are dimensions.
void readTable(const CatalogTable& table, std::vector<CatalogEntry>& out) {
  std::stringstream in{std::string(table.csv)};
  std::vector<std::string> header;
  double unit = 1e-3;  // mm, unless a comment line names the table's unit
  const std::string unitLine = "# unit: ";
  for (std::string line; std::getline(in, line);) {
    if (line.rfind(unitLine, 0) == 0) {
      unit = tableUnit(table, line.substr(unitLine.size()));
    }
    if (line.empty() || line.front() == '#') continue;
    const std::vector<std::string> cells = splitCommas(line);
    if (header.empty()) {
      header = cells;
      continue;
    }
    if (cells.size() != header.size())
      throw std::logic_error("catalogue table " + std::string(table.family) + ": row '" + line +
                             "' has " + std::to_string(cells.size()) + " cells, not " +
                             std::to_string(header.size()));
    CatalogEntry e;
    e.designation = cells[0];
    e.family = std::string(table.family);
    e.shape = shapeOf(table.family);
    e.unit = unit;
    for (std::size_t i = 1; i < cells.size(); ++i) {
      if (header[i] == "standard") continue;  // a note, not a dimension
      e.dims[header[i]] = std::stod(cells[i]);
    }
    out.push_back(std::move(e));
  }
}

}  // namespace

double CatalogEntry::dim(const std::string& key) const {
  const auto it = dims.find(key);
  if (it == dims.end())
    throw std::logic_error("catalogue row " + designation + " has no '" + key + "'");
  return it->second;
}

const std::vector<CatalogEntry>& sectionCatalog() {
  static const std::vector<CatalogEntry> entries = [] {
    std::vector<CatalogEntry> all;
    for (const CatalogTable& t : catalogTables()) readTable(t, all);
    return all;
  }();
  return entries;
}

std::string normalizedDesignation(std::string_view designation) {
  std::string s;
  for (const char c : designation)
    if (!std::isspace(static_cast<unsigned char>(c)))
      s += char(std::toupper(static_cast<unsigned char>(c)));
  // HE 300 B, the DIN spelling, is HEB300.
  if (s.size() > 3 && s.rfind("HE", 0) == 0 && std::isdigit(static_cast<unsigned char>(s[2]))) {
    const char series = s.back();
    if (series == 'A' || series == 'B' || series == 'M')
      s = std::string("HE") + series + s.substr(2, s.size() - 3);
  }
  return s;
}

const CatalogEntry* findCatalogEntry(std::string_view designation) {
  const std::string key = normalizedDesignation(designation);
  for (const CatalogEntry& e : sectionCatalog())
    if (normalizedDesignation(e.designation) == key) return &e;
  return nullptr;
}

namespace {

/// An I-section's dimensions in metres: h, b, tw, tf and the root radius r. The US W table
/// prints d, bf and kdes, the flange's outer face to the web toe of the fillet (r = kdes - tf).
struct IDims {
  double h, b, tw, tf, r;
};
IDims iDims(const CatalogEntry& e) {
  if (e.dims.contains("kdes"))
    return {e.metres("d"), e.metres("bf"), e.metres("tw"), e.metres("tf"),
            e.metres("kdes") - e.metres("tf")};
  return {e.metres("h"), e.metres("b"), e.metres("tw"), e.metres("tf"), e.metres("r")};
}

/// A rectangular hollow section's dimensions in metres: h, b, t and the corner radii. The US
/// HSS table prints H, B and the design wall t_des; AISC calculates with corner radii 2 t_des
/// outside and t_des inside (Steel Construction Manual, Part 1, on HSS properties).
struct HollowDims {
  double h, b, t, rOut, rIn;
};
HollowDims hollowDims(const CatalogEntry& e) {
  if (e.dims.contains("t_des")) {
    const double t = e.metres("t_des");
    return {e.metres("H"), e.metres("B"), t, 2 * t, t};
  }
  return {e.metres("h"), e.metres("b"), e.metres("t"), e.metres("r_out"), e.metres("r_in")};
}

/// A circular hollow section's outside diameter and wall in metres (US HSS: OD and t_des).
std::pair<double, double> tubeDims(const CatalogEntry& e) {
  if (e.dims.contains("t_des")) return {e.metres("OD"), e.metres("t_des")};
  return {e.metres("D"), e.metres("t")};
}

/// The row's outline in the drawing axes of StandardSections (y along the depth h).
std::vector<OutlineLoop> outlineOf(const CatalogEntry& e) {
  const auto d = [&](const char* k) { return e.metres(k); };
  switch (e.shape) {
    case CatalogShape::iSection: {
      const IDims i = iDims(e);
      return iSectionOutline(i.h, i.b, i.tw, i.tf, i.r);
    }
    case CatalogShape::channel:
      return channelOutline(d("h"), d("b"), d("tw"), d("tf"), d("r"), d("r_toe"),
                            e.dim("taper"));
    case CatalogShape::angle: return angleOutline(d("h"), d("b"), d("t"), d("r"), d("r_toe"));
    case CatalogShape::rectangularHollow: {
      const HollowDims r = hollowDims(e);
      return hollowRectangleOutline(r.h, r.b, r.t, r.rOut, r.rIn);
    }
    case CatalogShape::circularHollow: break;
  }
  throw std::logic_error("a circular hollow section has no straight-sided outline");
}

}  // namespace

Section catalogSection(const CatalogEntry& e, std::string name, const Material& m) {
  const auto d = [&](const char* k) { return e.metres(k); };
  switch (e.shape) {
    case CatalogShape::iSection: {
      const IDims i = iDims(e);
      return iSection(std::move(name), m, i.h, i.b, i.tw, i.tf, i.r);
    }
    case CatalogShape::channel:
      return channelSection(std::move(name), m, d("h"), d("b"), d("tw"), d("tf"), d("r"),
                            d("r_toe"), e.dim("taper"));
    case CatalogShape::angle:
      return angleSection(std::move(name), m, d("h"), d("b"), d("t"), d("r"), d("r_toe"));
    case CatalogShape::circularHollow: {
      const auto [D, t] = tubeDims(e);
      return Section::tube(std::move(name), m, D, t);
    }
    case CatalogShape::rectangularHollow: {
      const HollowDims r = hollowDims(e);
      return hollowRectangleSection(std::move(name), m, r.h, r.b, r.t, r.rOut, r.rIn);
    }
  }
  throw std::logic_error("unknown catalogue shape");
}

CatalogProperties catalogProperties(const CatalogEntry& e) {
  CatalogProperties p;
  // The torsion constant (and a tube's A and I) as the model's section has them; the material
  // plays no part in those.
  const Section s = catalogSection(e, e.designation, Material::fromEnu("steel", 210e9, 0.3, 0));
  p.It = s.J;
  if (e.shape == CatalogShape::circularHollow) {
    const auto [D, t] = tubeDims(e);
    const double Di = D - 2 * t;
    p.A = s.A;
    p.Iy = p.Iz = s.Iz;
    p.Wely = p.Welz = s.Iz / (D / 2);
    p.Wply = p.Wplz = (D * D * D - Di * Di * Di) / 6;  // twice the half ring's first moment
    return p;
  }
  // The drawing's y runs along the depth: the tables' Iy (strong) is int y^2 dA, about the
  // axis across the depth, and their Iz is int z^2 dA.
  const std::vector<OutlineLoop> loops = outlineOf(e);
  const OutlineProperties o = outlineProperties(loops);
  p.A = o.A;
  p.Iy = o.Izz;
  p.Iz = o.Iyy;
  const BendingModuli strong = bendingModuli(loops, 1, 0, p.Iy);
  const BendingModuli weak = bendingModuli(loops, 0, 1, p.Iz);
  p.Wely = strong.Wel;
  p.Wply = strong.Wpl;
  p.Welz = weak.Wel;
  p.Wplz = weak.Wpl;
  if (e.shape == CatalogShape::angle) {
    p.Iu = o.principalIz;
    p.Iv = o.principalIy;
  }
  return p;
}

}  // namespace beamrotor
