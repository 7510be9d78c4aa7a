// The section catalogue: rolled and hollow steel shapes by designation (IPE300, HEB200,
// UPN160, L100x100x10, CHS168.3x8, RHS200x100x8, SHS100x100x5-CF; the US W14X90,
// HSS8X8X1/2, HSS6.625X0.280), their dimensions read from
// the compiled-in tables (CatalogTables.hpp, sources cited in each table), and from those
// dimensions the section the model uses and the properties the steel tables print.
//
// Axes: the tables' names. y-y is the strong axis (the one bending in the web's plane is
// about), z-z the weak one; a catalogue Iy is the second moment about y-y. A member's local
// axes are named the other way round (local y runs along the depth, so a planar model bends
// about local z): the section built here has Section::Iz = the table's Iy and Section::Iy =
// the table's Iz, and a planar frame of catalogue sections bends about their strong axis.
#pragma once

#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "fem/model/Section.hpp"

namespace beamrotor {

enum class CatalogShape { iSection, channel, angle, circularHollow, rectangularHollow };

/// One row of a table: its designation, family and dimensions (as printed, in the table's
/// unit: mm unless its comment lines say `# unit: in`; a channel's taper a slope).
struct CatalogEntry {
  std::string designation;  ///< e.g. "IPE300"
  std::string family;       ///< the table, e.g. "IPE"
  CatalogShape shape = CatalogShape::iSection;
  std::map<std::string, double> dims;
  double unit = 1e-3;  ///< the table's length unit in metres
  double dim(const std::string& key) const;  ///< as printed; throws std::logic_error when absent
  double metres(const std::string& key) const { return dim(key) * unit; }
};

/// Every row of every table, table by table in file order.
const std::vector<CatalogEntry>& sectionCatalog();

/// A designation compared without spaces and case: "IPE 300", "ipe300" and "IPE300" are one;
/// "HE 300 B" is HEB300.
std::string normalizedDesignation(std::string_view designation);

/// The row of that designation, or nullptr.
const CatalogEntry* findCatalogEntry(std::string_view designation);

/// The properties a steel table prints, computed from the row's dimensions (SI units), in the
/// tables' axes (y-y strong). Angles: Iy, Iz about the axes parallel to the legs (y-y parallel
/// to the leg b, so Iy bends the leg h), Iu and Iv the principal ones (0 for other shapes).
struct CatalogProperties {
  double A = 0;
  double Iy = 0, Iz = 0;
  double It = 0;
  double Wely = 0, Welz = 0;
  double Wply = 0, Wplz = 0;
  double Iu = 0, Iv = 0;
};

CatalogProperties catalogProperties(const CatalogEntry& entry);

/// The model's section for the row (fem/model/StandardSections): local y along the depth, so
/// its Iz is the table's Iy (see the axes note above).
Section catalogSection(const CatalogEntry& entry, std::string name, const Material& m);

}  // namespace beamrotor
