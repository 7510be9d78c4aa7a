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

constexpr double mm = 1e-3;

CatalogShape shapeOf(std::string_view family) {
  if (family == "UPN") return CatalogShape::channel;
  if (family == "L") return CatalogShape::angle;
  if (family == "CHS") return CatalogShape::circularHollow;
  if (family == "RHS" || family == "SHS") return CatalogShape::rectangularHollow;
  return CatalogShape::iSection;  // IPE, HEA, HEB, HEM
}

std::vector<std::string> splitCommas(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream in(line);
  for (std::string cell; std::getline(in, cell, ',');) cells.push_back(cell);
  return cells;
}

/// The rows of one table: comment lines start with '#', the first other line names the
/// columns, the first column is the designation and the numeric columns are dimensions.
void readTable(const CatalogTable& table, std::vector<CatalogEntry>& out) {
  std::stringstream in{std::string(table.csv)};
  std::vector<std::string> header;
  for (std::string line; std::getline(in, line);) {
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

/// The row's outline in the drawing axes of StandardSections (y along the depth h).
std::vector<OutlineLoop> outlineOf(const CatalogEntry& e) {
  const auto d = [&](const char* k) { return e.dim(k) * mm; };
  switch (e.shape) {
    case CatalogShape::iSection: return iSectionOutline(d("h"), d("b"), d("tw"), d("tf"), d("r"));
    case CatalogShape::channel:
      return channelOutline(d("h"), d("b"), d("tw"), d("tf"), d("r"), d("r_toe"),
                            e.dim("taper"));
    case CatalogShape::angle: return angleOutline(d("h"), d("b"), d("t"), d("r"), d("r_toe"));
    case CatalogShape::rectangularHollow:
      return hollowRectangleOutline(d("h"), d("b"), d("t"), d("r_out"), d("r_in"));
    case CatalogShape::circularHollow: break;
  }
  throw std::logic_error("a circular hollow section has no straight-sided outline");
}

}  // namespace

Section catalogSection(const CatalogEntry& e, std::string name, const Material& m) {
  const auto d = [&](const char* k) { return e.dim(k) * mm; };
  switch (e.shape) {
    case CatalogShape::iSection:
      return iSection(std::move(name), m, d("h"), d("b"), d("tw"), d("tf"), d("r"));
    case CatalogShape::channel:
      return channelSection(std::move(name), m, d("h"), d("b"), d("tw"), d("tf"), d("r"),
                            d("r_toe"), e.dim("taper"));
    case CatalogShape::angle:
      return angleSection(std::move(name), m, d("h"), d("b"), d("t"), d("r"), d("r_toe"));
    case CatalogShape::circularHollow: return Section::tube(std::move(name), m, d("D"), d("t"));
    case CatalogShape::rectangularHollow:
      return hollowRectangleSection(std::move(name), m, d("h"), d("b"), d("t"), d("r_out"),
                                    d("r_in"));
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
    const double D = e.dim("D") * mm, t = e.dim("t") * mm, Di = D - 2 * t;
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
