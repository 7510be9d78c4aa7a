// Deck reader, part 1: materials, cross-sections, the segments of the line and its points
// (a frame's nodes and members: ReadFrame.cpp).
#include <cmath>
#include <limits>

#include "fem/model/StandardSections.hpp"
#include "problems/deck/DeckReader.hpp"
#include "problems/deck/catalog/SectionCatalog.hpp"
#include "problems/deck/ReaderContext.hpp"
#include "problems/deck/parse/Suggest.hpp"

namespace beamrotor::reader {

namespace {

/// The material a section names; may be left out when the deck has exactly one.
const Material& materialFor(const Context& c, const Field& section) {
  std::vector<std::string> names;
  for (const Material& m : c.materials) names.push_back(m.name);
  auto f = section.get("material");
  if (!f) {
    if (c.materials.size() == 1) return c.materials.front();
    DeckPlace at = section.place();
    at.field = section.path() + ".material";
    throw DeckError(
        section.file(), at,
        c.materials.empty()
            ? "missing required field 'material' (and the deck defines no materials)"
            : "missing required field 'material' (materials: " + joinNames(names) + ")");
  }
  const std::string name = f->name();
  for (const Material& m : c.materials)
    if (m.name == name) return m;
  f->fail("no material named '" + name + "'" + didYouMean(name, names) +
          " (materials: " + joinNames(names) + ")");
}

/// A standard shape from its dimensions (fem/model/StandardSections): `keys` the required
/// dimensions in the constructor's order, `optional` those that default to 0.
template <class Make>
std::shared_ptr<const Section> readShape(const Context& c, const Field& f,
                                         const std::vector<std::string>& keys,
                                         const std::vector<std::string>& optional, Make make) {
  std::vector<double> v;
  for (const std::string& k : keys)  // a root radius may be 0 (welded, sharp)
    v.push_back(k == "r" ? f.require(k).nonNegative(c.evaluator, dim::length)
                         : f.require(k).positive(c.evaluator, dim::length));
  for (const std::string& k : optional) {  // a channel's taper is a slope, the rest lengths
    const Dimension& d = k == "taper" ? dim::none : dim::length;
    v.push_back(f.get(k) ? f.get(k)->nonNegative(c.evaluator, d) : 0.0);
  }
  return std::make_shared<Section>(make(v));
}

/// The catalogue row a designation names; fails at the field suggesting the nearest one,
/// compared as designations are (without spaces and case) and named as its table spells it.
const CatalogEntry& catalogEntryAt(const Field& field) {
  const std::string designation = field.text();
  if (const CatalogEntry* entry = findCatalogEntry(designation)) return *entry;
  std::vector<std::string> known;
  for (const CatalogEntry& e : sectionCatalog())
    known.push_back(normalizedDesignation(e.designation));
  const std::string near = closestMatch(normalizedDesignation(designation), known, 2);
  const CatalogEntry* nearest = near.empty() ? nullptr : findCatalogEntry(near);
  field.fail("no section '" + designation + "' in the catalogue" +
             (nearest ? "; did you mean '" + nearest->designation + "'?" : std::string()) +
             " (families: IPE, HEA, HEB, HEM, UPN, L, CHS, RHS, SHS; see FORMAT.md)");
}

/// A section picked from the catalogue by designation (problems/deck/catalog): its shape and
/// dimensions come from the table, so no shape key may be given beside it. A list of
/// designations with `pick` (1 for the first) lets a parameter choose one, so that sweeps and
/// design studies can: every designation in the list must exist.
std::shared_ptr<const Section> readCatalogSection(Context& c, const Field& f,
                                                  const std::string& name) {
  f.allowOnly({"name", "catalog", "pick", "material"}, "a catalogue section");
  const Field listed = f.require("catalog");
  const auto pick = f.get("pick");
  if (listed.isList() != pick.has_value())
    (pick ? *pick : listed)
        .fail(pick ? "`pick` chooses from a list of designations: give `catalog` a list"
                   : "a list of designations needs `pick` (1 for the first) to choose one");
  std::vector<const CatalogEntry*> entries;
  for (const Field& item : listed.itemsOrSingle()) entries.push_back(&catalogEntryAt(item));
  if (entries.empty()) listed.fail("the list of designations is empty");
  const CatalogEntry& entry =
      *entries[pick ? std::size_t(pick->integer(c.evaluator, 1, int(entries.size())) - 1) : 0];
  const Material& m = materialFor(c, f);
  c.deck.catalogSections.push_back({name, entry.designation, catalogProperties(entry)});
  return std::make_shared<Section>(catalogSection(entry, name, m));
}

std::shared_ptr<const Section> readSection(Context& c, const Field& f, const std::string& name) {
  const ExpressionEvaluator& ev = c.evaluator;
  if (f.has("catalog") && !f.has("shape")) return readCatalogSection(c, f, name);
  const std::vector<std::string> common{"name", "shape", "material"};
  const std::string shape = f.require("shape").choice(
      {"circle", "tube", "rectangle", "I", "channel", "angle", "rhs", "general"});
  auto keys = [&](std::vector<std::string> own) {
    own.insert(own.begin(), common.begin(), common.end());
    return own;
  };
  if (shape == "circle") f.allowOnly(keys({"D"}), "a circle section");
  if (shape == "tube") f.allowOnly(keys({"D", "t"}), "a tube section");
  if (shape == "rectangle") f.allowOnly(keys({"b", "h"}), "a rectangle section");
  if (shape == "I") f.allowOnly(keys({"h", "b", "tw", "tf", "r"}), "an I section");
  if (shape == "channel")
    f.allowOnly(keys({"h", "b", "tw", "tf", "r", "r_toe", "taper"}), "a channel");
  if (shape == "angle") f.allowOnly(keys({"h", "b", "t", "r", "r_toe"}), "an angle");
  if (shape == "rhs") f.allowOnly(keys({"h", "b", "t", "r_out", "r_in"}), "a hollow rectangle");
  if (shape == "general")
    f.allowOnly(
        keys({"A", "I", "Iy", "Iz", "J", "kappa", "kappa_y", "kappa_z", "depth", "width"}),
        "a general section");
  const Material& m = materialFor(c, f);
  if (std::isnan(m.nu) && (shape == "circle" || shape == "tube" || shape == "rectangle"))
    f.fail("a " + shape + " section's shear coefficient needs Poisson's ratio, and material '" +
           m.name + "' gives E and G apart (E / (2 G) - 1 = " + formatNumber(m.E / (2 * m.G) - 1) +
           " is none): give the material nu");

  if (shape == "circle")
    return std::make_shared<Section>(
        Section::circle(name, m, f.require("D").positive(ev, dim::length)));
  if (shape == "tube") {
    const double D = f.require("D").positive(ev, dim::length);
    const Field tf = f.require("t");
    const double t = tf.positive(ev, dim::length);
    if (!(2 * t <= D))
      tf.fail("wall thickness must not exceed half the diameter (D/2 = " + formatNumber(D / 2) +
              "), got " + formatNumber(t));
    return std::make_shared<Section>(Section::tube(name, m, D, t));
  }
  if (shape == "rectangle") {
    const double b = f.require("b").positive(ev, dim::length);
    const double h = f.require("h").positive(ev, dim::length);
    return std::make_shared<Section>(Section::rectangle(name, m, b, h));
  }
  if (shape == "I")
    return readShape(c, f, {"h", "b", "tw", "tf", "r"}, {}, [&](const std::vector<double>& v) {
      return iSection(name, m, v[0], v[1], v[2], v[3], v[4]);
    });
  if (shape == "channel")
    return readShape(c, f, {"h", "b", "tw", "tf", "r"}, {"r_toe", "taper"},
                     [&](const std::vector<double>& v) {
                       return channelSection(name, m, v[0], v[1], v[2], v[3], v[4], v[5], v[6]);
                     });
  if (shape == "angle")
    return readShape(c, f, {"h", "b", "t", "r"}, {"r_toe"}, [&](const std::vector<double>& v) {
      return angleSection(name, m, v[0], v[1], v[2], v[3], v[4]);
    });
  if (shape == "rhs")
    return readShape(c, f, {"h", "b", "t"}, {"r_out", "r_in"},
                     [&](const std::vector<double>& v) {
                       return hollowRectangleSection(name, m, v[0], v[1], v[2], v[3], v[4]);
                     });
  // General: I sets both second moments; Iy defaults to Iz (and the other way round).
  const double A = f.require("A").positive(ev, dim::area);
  auto I = f.get("I"), Iy = f.get("Iy"), Iz = f.get("Iz");
  if (I && (Iy || Iz)) (Iy ? *Iy : *Iz).fail("give either I or Iy/Iz, not both");
  if (!I && !Iy && !Iz) {
    DeckPlace at = f.place();
    at.field = f.path() + ".Iz";
    throw DeckError(f.file(), at, "missing required field 'Iz' (or 'I' for both axes)");
  }
  const Dimension& I4 = dim::secondMoment;
  const double Ival = I ? I->positive(ev, I4) : 0;
  const double IzVal = I ? Ival : Iz ? Iz->positive(ev, I4) : Iy->positive(ev, I4);
  const double IyVal = I ? Ival : Iy ? Iy->positive(ev, I4) : IzVal;
  const double J = f.get("J") ? f.get("J")->nonNegative(ev, I4) : 0;
  auto kappa = f.get("kappa");
  const double k = kappa ? kappa->nonNegative(ev, dim::none) : 0;
  const double ky = f.get("kappa_y") ? f.get("kappa_y")->nonNegative(ev, dim::none) : k;
  const double kz = f.get("kappa_z") ? f.get("kappa_z")->nonNegative(ev, dim::none) : k;
  const double depth = f.get("depth") ? f.get("depth")->positive(ev, dim::length) : 0;
  const double width = f.get("width") ? f.get("width")->positive(ev, dim::length) : 0;
  Section s = Section::general(name, m, A, IyVal, IzVal, J, ky, kz, 0);
  if (depth > 0) s.setExtent(depth, width);
  // kappa: 0 given on purpose is a shear-rigid section; only a missing kappa is a gap.
  const bool kappaGiven = kappa || (f.has("kappa_y") && f.has("kappa_z"));
  const DeckSectionGaps gaps{name, f.path(), f.place(), depth == 0, width == 0, !f.has("J"),
                             !kappaGiven};
  if (gaps.depth || gaps.width || gaps.J || gaps.kappa) c.deck.sectionGaps.push_back(gaps);
  return std::make_shared<Section>(std::move(s));
}

/// A model without beams: named points only, `at` their x coordinate (m, default 0).
void readPointModel(Context& c) {
  const auto points = c.root.get("points");
  if ((!points || points->isNull()) && modelFree(c)) return;  // a mechanism alone
  if (!points || points->isNull())
    c.root.fail(
        "the deck needs segments (a line of beams) or, for a model without beams, "
        "points carrying masses and springs");
  TakenNames names;
  for (const Field& f : points->items()) {
    f.allowOnly({"name", "at"}, "a point");
    const Field nf = f.require("name");
    const std::string name = nf.name();
    claimName(nf, name, names, "a point");
    const double x = f.has("at") ? f.require("at").number(c.evaluator, dim::length) : 0.0;
    c.deck.points.push_back({name, x, f.place()});
  }
  if (c.deck.points.empty()) points->fail("the list of points is empty");
}

}  // namespace

void readMaterials(Context& c) {
  auto block = c.root.get("materials");
  if (!block || block->isNull()) return;
  TakenNames names;
  for (const Field& f : block->items()) {
    f.allowOnly({"name", "E", "nu", "G", "rho", "alpha"}, "a material");
    const std::string name = f.require("name").name();
    claimName(f.require("name"), name, names, "a material");
    const ExpressionEvaluator& ev = c.evaluator;
    const double E = f.require("E").positive(ev, dim::pressure);
    const double rho = f.get("rho") ? f.get("rho")->nonNegative(ev, dim::density) : 0;
    auto nuField = f.get("nu"), GField = f.get("G");
    if (!nuField && !GField) {
      DeckPlace at = f.place();
      at.field = f.path() + ".nu";
      throw DeckError(f.file(), at, "missing required field 'nu' (Poisson's ratio; or give G)");
    }
    // E and G are independent when both are given (timber, fibre composites); nu then only
    // sets the Cowper shear coefficients of circle, tube and rectangle sections.
    const double G = GField ? GField->positive(ev, dim::pressure) : 0;
    const double isotropicNu = E / (2 * G) - 1;
    const bool isotropic = isotropicNu > -1 && isotropicNu < 0.5;
    const double nu = nuField ? nuField->number(ev, dim::none)
                      : isotropic ? isotropicNu
                                  : std::numeric_limits<double>::quiet_NaN();  // unknown
    if (nuField && !(nu > -1 && nu < 0.5))
      nuField->fail("Poisson's ratio must lie in (-1, 0.5), got " + formatNumber(nu));
    Material m{name, E, nu, GField ? G : E / (2 * (1 + nu)), rho};
    if (auto alpha = f.get("alpha")) m.alpha = alpha->nonNegative(ev, dim::thermalExpansion);
    c.materials.push_back(m);
  }
}

void readSections(Context& c) {
  if (!c.root.has("sections") && !c.root.has("segments") && !c.root.has("members"))
    return;  // a model without beams
  auto block = c.root.require("sections");
  TakenNames names;
  for (const Field& f : block.items()) {
    if (!f.isMap()) f.fail("expected a map describing a section, got " + f.describe());
    const std::string name = f.require("name").name();
    claimName(f.require("name"), name, names, "a section");
    try {
      c.sections.push_back(readSection(c, f, name));
    } catch (const std::invalid_argument& e) {
      f.fail(e.what());  // the core's own range checks, should one of ours miss
    }
  }
  if (c.sections.empty()) block.fail("the deck needs at least one section");
}

void readSegmentMesh(const Context& c, const Field& f, DeckSegment& s) {
  const ExpressionEvaluator& ev = c.evaluator;
  const Field sf = f.require("section");
  s.sectionName = sf.name();
  std::vector<std::string> sectionNames;
  for (const auto& sec : c.sections) {
    if (sec->name == s.sectionName) s.section = sec;
    sectionNames.push_back(sec->name);
  }
  if (!s.section)
    sf.fail("no section named '" + s.sectionName + "'" + didYouMean(s.sectionName, sectionNames) +
            " (sections: " + joinNames(sectionNames) + ")");
  auto count = f.get("elements"), size = f.get("size");
  if (count && size) size->fail("give either elements or size, not both");
  if (!count && !size) {
    DeckPlace at = f.place();
    at.field = f.path() + ".elements";
    throw DeckError(f.file(), at,
                    "missing required field 'elements' (or 'size', the largest element length)");
  }
  if (count) s.elements = count->integer(ev, 1, kMaxElements);
  if (size) s.size = size->positive(ev, dim::length);
  s.options = c.deck.beam;
  if (auto form = f.get("formulation")) s.options.theory = formulationOf(*form);
  const bool linearTimoshenko =
      s.options.theory == BeamTheory::timoshenkoLinearFullIntegration ||
      s.options.theory == BeamTheory::timoshenkoLinearReducedIntegration;
  if (linearTimoshenko && !(s.section->kappaY > 0 && s.section->kappaZ > 0))
    sf.fail("the linear Timoshenko element needs a shear coefficient: give the section kappa");
}

void readLine(Context& c) {
  if (c.root.has("members") || c.root.has("nodes")) {
    if (auto segments = c.root.get("segments"))
      segments->fail("give either segments (a line along x) or nodes and members (a frame), "
                     "not both");
    readFrame(c);
    return;
  }
  if (!c.root.has("segments")) {
    readPointModel(c);
    return;
  }
  const ExpressionEvaluator& ev = c.evaluator;
  // 1. Segments, in order from the start of the line.
  const Field block = c.root.require("segments");
  TakenNames names;
  std::vector<Field> lengths;
  double elements = 0;
  for (const Field& f : block.items()) {
    f.allowOnly({"name", "length", "section", "elements", "size", "formulation", "axial_force"},
                "a segment");
    DeckSegment s;
    s.place = f.place();
    if (auto n = f.get("name")) {
      s.name = n->name();
      claimName(*n, s.name, names, "a segment");
    }
    lengths.push_back(f.require("length"));
    s.length = lengths.back().positive(ev, dim::length);
    readSegmentMesh(c, f, s);
    if (auto axial = f.get("axial_force")) {
      if (c.deck.dimension != "lateral")
        axial->fail("axial_force gives a lateral rotor's shaft its axial force; planar and 3d "
                    "models take it from their loads (buckling, second_order, prestressed)");
      s.axialForce = axial->number(ev, dim::force);
    }
    elements += s.elementEstimate();
    if (!(elements <= kMaxElements))
      f.fail("the line would have more than " + std::to_string(kMaxElements) +
             " elements; use fewer elements or a larger size");
    c.deck.segments.push_back(std::move(s));
  }
  if (c.deck.segments.empty()) block.fail("the deck needs at least one segment");
  // A segment within the line's geometric tolerance (meshes/LineBuilder) would get no element.
  const double tolerance = 1e-12 * std::max(1.0, c.deck.length());
  for (std::size_t k = 0; k < lengths.size(); ++k)
    if (c.deck.segments[k].length <= tolerance)
      lengths[k].fail("segment " +
                      (c.deck.segments[k].name.empty() ? std::to_string(k + 1)
                                                       : "'" + c.deck.segments[k].name + "'") +
                      " is " + formatNumber(c.deck.segments[k].length) +
                      " m long, within the geometric tolerance (" + formatNumber(tolerance) +
                      " m) of this line: it would get no element; make it longer or leave it "
                      "out");

  // 2. Points: "start" and "end" always exist; the deck's own must lie on the line.
  const double L = c.deck.length();
  c.deck.points.push_back({"start", 0, block.place()});
  c.deck.points.push_back({"end", L, block.place()});
  TakenNames pointNames{"start", "end"};
  if (auto points = c.root.get("points"); points && !points->isNull()) {
    for (const Field& f : points->items()) {
      f.allowOnly({"name", "at"}, "a point");
      const Field nf = f.require("name");
      const std::string name = nf.name();
      if (name == "start" || name == "end")
        nf.fail("'" + name + "' is predefined (the " + name + " of the line); choose another name");
      claimName(nf, name, pointNames, "a point");
      const Field at = f.require("at");
      const double x = at.number(ev, dim::length);
      const double tol = 1e-12 * std::max(1.0, L);
      if (x < -tol || x > L + tol)
        at.fail("point '" + name + "' at " + formatNumber(x) + " m lies outside the line (0 to " +
                formatNumber(L) + " m)");
      c.deck.points.push_back({name, std::clamp(x, 0.0, L), f.place()});
      if (int(c.deck.points.size()) + elements > kMaxElements)
        f.fail("too many points: the line would have more than " + std::to_string(kMaxElements) +
               " elements");
    }
  }
}

}  // namespace beamrotor::reader
