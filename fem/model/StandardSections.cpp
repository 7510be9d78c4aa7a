#include "fem/model/StandardSections.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "fem/model/SectionOutline.hpp"
#include "fem/model/ThinWalledShear.hpp"

namespace beamrotor {

namespace {

void requireShapeValue(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument(what);
}

bool positive(double v) { return std::isfinite(v) && v > 0; }
bool nonNegative(double v) { return std::isfinite(v) && v >= 0; }

/// A section from its outline (first loop outer), with everything the outline decides.
Section fromOutline(std::string name, Section::Shape shape, const Material& m,
                    const std::vector<OutlineLoop>& loops, double depth) {
  const OutlineProperties p = outlineProperties(loops);
  Section s;
  s.name = std::move(name);
  s.shape = shape;
  s.material = m;
  s.A = p.A;
  s.Iy = p.principalIy;
  s.Iz = p.principalIz;
  s.fibres = outlineFibres(loops.front(), p);
  for (const StressFibre& f : s.fibres) {
    s.outerY = std::max(s.outerY, std::abs(f.y) + f.radius);
    s.outerZ = std::max(s.outerZ, std::abs(f.z) + f.radius);
  }
  s.depth = depth;
  return s;
}

/// Shear coefficient and peak factor along y (from the flow's energy and peak for shear along
/// y) and along z, into s.
void setShear(Section& s, const ShearFlow& alongY, double Iz, const ShearFlow& alongZ, double Iy) {
  const ThinWalledShear y = thinWalledShear(alongY.energy, alongY.peak, Iz, s.A);
  const ThinWalledShear z = thinWalledShear(alongZ.energy, alongZ.peak, Iy, s.A);
  s.kappaY = y.kappa;
  s.shearPeakY = y.peak;
  s.kappaZ = z.kappa;
  s.shearPeakZ = z.peak;
}

/// The flow of one chain walked from a free end, and the energy of `copies` equal chains.
ShearFlow times(ShearFlow f, int copies) {
  f.energy *= copies;
  return f;
}

/// St Venant torsion of a wall taken as a rectangle `length` long and t thick, `freeEnds` (0, 1
/// or 2) of its ends free (not running into another wall): (length - 0.315 freeEnds t) t^3 / 3,
/// the rectangle's series to first order, each free end relieving 0.105 t^4 (Roark's Formulas
/// for Stress and Strain, 7th ed., Table 10.7; the European tables' 0.63 tf for a flange's two
/// tips).
double wallTorsion(double length, double t, int freeEnds) {
  return (length - 0.315 * freeEnds * t) * std::pow(t, 3) / 3;
}

/// The torsion a filleted L junction adds to its two walls (thicknesses ta, tb, meeting at a
/// right angle with root radius r): alpha D^4, with D = 2 ((3 r + ta + tb) - sqrt(2 (2 r + ta)
/// (2 r + tb))) the largest circle inscribed in the corner and alpha = (t / t1)(0.07 + 0.076 r /
/// t1), t and t1 the smaller and larger of ta, tb (El Darwish & Johnston 1965, as in Roark's
/// Formulas for Stress and Strain, 7th ed., Table 10.7, L section).
double lJunctionTorsion(double ta, double tb, double r) {
  const double t = std::min(ta, tb), t1 = std::max(ta, tb);
  const double D = 2 * ((3 * r + ta + tb) - std::sqrt(2 * (2 * r + ta) * (2 * r + tb)));
  return t / t1 * (0.07 + 0.076 * r / t1) * std::pow(D, 4);
}

/// What a toe rounded with radius rToe takes from the torsion of its wall (thickness t): the
/// rounding removes rToe^2 (1 - pi / 4) of the wall's end, taken as that area over t off the
/// wall's length. Measured against the stress function of an angle's outline (rounded toes
/// against sharp ones): L 40x40x4 loses 21.0 mm^4 (this gives 20.6), L 100x100x10 454 (515).
double roundedToeTorsion(double t, double rToe) {
  return rToe * rToe * (1 - std::numbers::pi / 4) * t * t / 3;
}

}  // namespace

std::vector<OutlineLoop> iSectionOutline(double h, double b, double tw, double tf, double r) {
  const double y = h / 2, yi = h / 2 - tf, z = b / 2, zw = tw / 2;
  return {{{-y, -z},    {-yi, -z},    {-yi, -zw, r}, {yi, -zw, r}, {yi, -z},   {y, -z},
           {y, z},      {yi, z},      {yi, zw, r},   {-yi, zw, r}, {-yi, z},   {-y, z}}};
}

std::vector<OutlineLoop> channelOutline(double h, double b, double tw, double tf, double r,
                                        double rToe, double taper) {
  const double y = h / 2, atRoot = y - tf - taper * (b / 2 - tw), atToe = y - tf + taper * b / 2;
  return {{{-y, 0},           {y, 0},          {y, b},           {atToe, b, rToe},
           {atRoot, tw, r},   {-atRoot, tw, r}, {-atToe, b, rToe}, {-y, b}}};
}

std::vector<OutlineLoop> angleOutline(double h, double b, double t, double r, double rToe) {
  return {{{0, 0}, {h, 0}, {h, t, rToe}, {t, t, r}, {t, b, rToe}, {0, b}}};
}

std::vector<OutlineLoop> hollowRectangleOutline(double h, double b, double t, double ro,
                                                double ri) {
  const double y = h / 2, z = b / 2, yi = y - t, zi = z - t;
  return {{{-y, -z, ro}, {y, -z, ro}, {y, z, ro}, {-y, z, ro}},
          {{-yi, -zi, ri}, {-yi, zi, ri}, {yi, zi, ri}, {yi, -zi, ri}}};
}

Section iSection(std::string name, const Material& m, double h, double b, double tw, double tf,
                 double r) {
  requireShapeValue(positive(h) && positive(b) && positive(tw) && positive(tf) && nonNegative(r),
          "I-section dimensions h, b, tw, tf must be positive and r non-negative");
  requireShapeValue(2 * tf < h, "the flanges (2 tf) must be thinner than the depth h");
  requireShapeValue(tw + 2 * r <= b, "the web and its root fillets (tw + 2 r) must fit in the width b");
  requireShapeValue(2 * (tf + r) <= h, "the flanges and root fillets (2 (tf + r)) must fit in the depth h");
  Section s = fromOutline(std::move(name), Section::Shape::iSection, m,
                          iSectionOutline(h, b, tw, tf, r), h);
  const double z = b / 2;

  // Torsion: the formula the European rolled-section tables compute their It with
  // (ArcelorMittal Europe, "Sections and merchant bars", technical notes on the properties):
  // the flanges and the web as rectangles, 2/3 (b - 0.63 tf) tf^3 + 1/3 (h - 2 tf) tw^3, plus
  // the two web-flange junctions with their fillets, alpha D^4 each (El Darwish & Johnston
  // 1965): D = ((tf + r)^2 + tw (r + tw / 4)) / (2 r + tf), the diameter of the largest circle
  // inscribed in a junction, and alpha = (t / t1)(0.145 + 0.1 r / tf), t and t1 the smaller
  // and larger of tw, tf (tw / tf for every rolled shape). Roark's Formulas for Stress and
  // Strain (7th ed., Table 10.7) gives the same with 0.15 for 0.145, 1.7 % more junction.
  // Within half a printed digit of the 27 tabulated IPE, HE A and HE B rows tested
  // (tests/problems/test_section_catalog.cpp); IPE 300: 20.12 cm^4 as printed.
  const double flange = 2 * wallTorsion(b, tf, 2);
  const double web = wallTorsion(h - 2 * tf, tw, 0);
  const double D = ((tf + r) * (tf + r) + r * tw + tw * tw / 4) / (2 * r + tf);
  const double alpha = std::min(tf, tw) / std::max(tf, tw) * (0.145 + 0.1 * r / tf);
  s.J = flange + web + 2 * alpha * std::pow(D, 4);

  // Shear, midline model: flanges at y = +-d/2 (d = h - tf), web on z = 0. Along y the flow
  // runs from the four flange tips into the web; along z through each flange from tip to tip
  // (the web, on the axis of symmetry, carries none).
  const double d = h - tf;
  const std::vector<Wall> halfFlange{{d / 2, z, d / 2, 0, tf}};
  const ShearFlow tips = shearFlow(halfFlange, 0, 1, 0);
  ShearFlow webFlow = shearFlow({{d / 2, 0, -d / 2, 0, tw}}, 2 * tips.end, 1, 0);
  ShearFlow alongY{4 * tips.energy + webFlow.energy, 0, std::max(tips.peak, webFlow.peak)};
  const std::vector<Wall> walls{{d / 2, -z, d / 2, z, tf}, {-d / 2, -z, -d / 2, z, tf},
                                {d / 2, 0, -d / 2, 0, tw}};
  const ShearFlow alongZ = times(shearFlow({walls[0]}, 0, 0, 1), 2);
  setShear(s, alongY, midlineSecondMoment(walls, 1, 0), alongZ, midlineSecondMoment(walls, 0, 1));
  return s;
}

Section channelSection(std::string name, const Material& m, double h, double b, double tw,
                       double tf, double r, double rToe, double taper) {
  requireShapeValue(positive(h) && positive(b) && positive(tw) && positive(tf) && nonNegative(r) &&
              nonNegative(rToe) && nonNegative(taper),
          "channel dimensions h, b, tw, tf must be positive and r, r_toe, taper non-negative");
  requireShapeValue(tw < b, "a channel needs tw < b");
  // The inner faces of the flanges: tf thick at b/2, thinner towards the toes by the taper.
  const double y = h / 2, atRoot = y - tf - taper * (b / 2 - tw), atToe = y - tf + taper * b / 2;
  requireShapeValue(atRoot > 0, "the flanges (tf, with their taper) must leave room for the web");
  requireShapeValue(atToe < y, "the taper leaves the flange tips no thickness");
  const OutlineLoop outline = channelOutline(h, b, tw, tf, r, rToe, taper).front();
  Section s = fromOutline(std::move(name), Section::Shape::channel, m, {outline}, h);
  // The outline's centroid lies at e from the web's back; fromOutline measured the fibres
  // from it. The midline walls, from the same centroid: web at z = tw/2 - e, flanges to b - e.
  const OutlineProperties p = outlineProperties({outline});
  const double e = p.cz, d = h - tf, zw = tw / 2 - e, zt = b - e;
  const std::vector<Wall> chain{{d / 2, zt, d / 2, zw, tf}, {d / 2, zw, -d / 2, zw, tw},
                                {-d / 2, zw, -d / 2, zt, tf}};
  // Torsion: the European tables' rectangles as for I sections (flanges of the full width b,
  // the web between them), and the two web-flange corners as filleted L junctions
  // (lJunctionTorsion). A tapered flange enters with tf, its thickness halfway along. Against
  // the St Venant constant of the exact outline (Prandtl's stress function solved by finite
  // differences, tests/fem/model/test_open_section_torsion.cpp): 0.4 % to 1.4 % below on UPN 50
  // to 100, where the thin-walled sum L t^3 / 3 was 9 % to 10 % below (docs/section_catalog.md).
  s.J = 2 * wallTorsion(b, tf, 2) + wallTorsion(h - 2 * tf, tw, 0) +
        2 * lJunctionTorsion(tw, tf, r);
  setShear(s, shearFlow(chain, 0, 1, 0), midlineSecondMoment(chain, 1, 0),
           shearFlow(chain, 0, 0, 1), midlineSecondMoment(chain, 0, 1));
  return s;
}

double angleLegAngle(double h, double b, double t, double r, double rToe) {
  return outlineProperties(angleOutline(h, b, t, r, rToe)).principalAngle;
}

Section angleSection(std::string name, const Material& m, double h, double b, double t, double r,
                     double rToe) {
  requireShapeValue(positive(h) && positive(b) && positive(t) && nonNegative(r) && nonNegative(rToe),
          "angle dimensions h, b, t must be positive and r, r_toe non-negative");
  requireShapeValue(t < h && t < b, "the legs must be longer than the thickness t");
  const OutlineLoop outline = angleOutline(h, b, t, r, rToe).front();
  Section s = fromOutline(std::move(name), Section::Shape::angle, m, {outline}, std::max(h, b));
  // Midline legs from the heel's midline corner (t/2, t/2), in principal axes.
  const OutlineProperties p = outlineProperties({outline});
  const double c = std::cos(p.principalAngle), sn = std::sin(p.principalAngle);
  const auto local = [&](double y, double z) {
    return std::array<double, 2>{c * (y - p.cy) + sn * (z - p.cz),
                                 -sn * (y - p.cy) + c * (z - p.cz)};
  };
  const auto [y1, z1] = local(h, t / 2);
  const auto [y0, z0] = local(t / 2, t / 2);
  const auto [y2, z2] = local(t / 2, b);
  const std::vector<Wall> chain{{y1, z1, y0, z0, t}, {y0, z0, y2, z2, t}};
  // Torsion: the legs as rectangles, the leg h with its two free ends (its toe and the heel's
  // back) and the rest of the leg b, b - t, with its toe, plus the filleted root as an L junction
  // (lJunctionTorsion), less the two rounded toes (roundedToeTorsion): Roark's L section (7th
  // ed., Table 10.7) without its terms in (t / h)^4. Against the St Venant constant of the exact
  // outline (tests/fem/model/test_open_section_torsion.cpp), over the whole catalogue: 1.1 % to
  // 5.1 % above (the most where r / t is largest), where the thin-walled sum L t^3 / 3 lay 2.5 %
  // to 14 % below; against the SCI Blue Book's printed It (51 rows,
  // tests/problems/test_section_catalog.cpp), -1.3 % to +2.7 % (docs/section_catalog.md).
  s.J = wallTorsion(h, t, 2) + wallTorsion(b - t, t, 1) + lJunctionTorsion(t, t, r) -
        2 * roundedToeTorsion(t, rToe);
  setShear(s, shearFlow(chain, 0, 1, 0), midlineSecondMoment(chain, 1, 0),
           shearFlow(chain, 0, 0, 1), midlineSecondMoment(chain, 0, 1));
  return s;
}

Section hollowRectangleSection(std::string name, const Material& m, double h, double b, double t,
                               double ro, double ri) {
  requireShapeValue(positive(h) && positive(b) && positive(t) && nonNegative(ro) && nonNegative(ri),
          "hollow section dimensions h, b, t must be positive and the radii non-negative");
  requireShapeValue(2 * t < std::min(h, b), "the wall t must be thinner than half the smaller side");
  requireShapeValue(2 * ro <= std::min(h, b) && 2 * ri <= std::min(h, b) - 2 * t,
          "the corner radii must fit the sides");
  Section s = fromOutline(std::move(name), Section::Shape::hollowRectangle, m,
                          hollowRectangleOutline(h, b, t, ro, ri), h);

  // Torsion of a closed thin wall (EN 10219-2:2006, Annex B, after Bredt): It = t^3 p / 3 +
  // 2 K Ah with the midline's enclosed area Ah = (b - t)(h - t) - Rc^2 (4 - pi), perimeter
  // p = 2 ((b - t) + (h - t)) - 2 Rc (4 - pi), K = 2 t Ah / p, Rc = (ro + ri) / 2.
  const double Rc = (ro + ri) / 2, pi = std::numbers::pi;
  const double Ah = (b - t) * (h - t) - Rc * Rc * (4 - pi);
  const double perimeter = 2 * ((b - t) + (h - t)) - 2 * Rc * (4 - pi);
  s.J = std::pow(t, 3) * perimeter / 3 + 2 * (2 * t * Ah / perimeter) * Ah;

  // Shear, midline rectangle (corners sharp): by symmetry the flow vanishes where the axis of
  // the shear force crosses the wall, so each half is an open chain from there.
  const double hm = (h - t) / 2, bm = (b - t) / 2;
  const std::vector<Wall> walls{{hm, -bm, hm, bm, t}, {-hm, -bm, -hm, bm, t},
                                {-hm, bm, hm, bm, t}, {-hm, -bm, hm, -bm, t}};
  const std::vector<Wall> halfY{{hm, 0, hm, bm, t}, {hm, bm, -hm, bm, t}, {-hm, bm, -hm, 0, t}};
  const std::vector<Wall> halfZ{{0, bm, hm, bm, t}, {hm, bm, hm, -bm, t}, {hm, -bm, 0, -bm, t}};
  setShear(s, times(shearFlow(halfY, 0, 1, 0), 2), midlineSecondMoment(walls, 1, 0),
           times(shearFlow(halfZ, 0, 0, 1), 2), midlineSecondMoment(walls, 0, 1));
  return s;
}

}  // namespace beamrotor
