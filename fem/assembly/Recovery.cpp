#include "fem/assembly/Recovery.hpp"

#include "fem/assembly/ParallelParts.hpp"
#include "fem/assembly/SolutionPolynomials.hpp"
#include "fem/model/ShearStress.hpp"

namespace beamrotor {

ElementVector elementValues(const Element& element, const NodalField& field) {
  const auto d = element.dofs();
  ElementVector u(d.size());
  for (int a = 0; a < int(d.size()); ++a) u[a] = field(d[a].node, dofIndex(d[a].dof));
  return u;
}

std::array<double, kDofKinds> displacementAlong(const LineElement& element, const NodalField& field,
                                                double s, SpanLoad load) {
  return element.displacementAt(elementValues(element, field), s, load);
}

SectionForceSeries LoadedSolution::forceSeries(int element) const {
  if (polynomials) return polynomials->forces(element);
  const LineElement& line = *asLine(model->elements().at(element));
  return line.sectionForceSeries(elementValues(line, *displacement), spanOn(element, line));
}

std::array<Polynomial, 3> LoadedSolution::translationSeries(int element) const {
  return polynomials ? polynomials->translations(element) : recoveredTranslations(*this, element);
}

std::array<double, kDofKinds> LoadedSolution::displacementAt(int element, double s) const {
  const LineElement& line = *asLine(model->elements().at(element));
  return line.displacementAt(elementValues(line, *displacement), s, spanOn(element, line));
}

std::vector<ReactionComponent> namedElementForces(const Model& model, const NodalField& field) {
  std::vector<ReactionComponent> out;
  for (const auto& [name, index] : model.namedElements()) {
    const Element& e = *model.elements().at(index);
    const ElementVector f = e.endForces(elementValues(e, field));
    const auto d = e.dofs();
    for (int a = 0; a < int(d.size()); ++a)
      if (d[a].node == d[0].node) out.push_back({name, d[a].node, d[a].dof, -f[a]});
  }
  return out;
}

namespace {

/// Fills the sides of the nodes in `sides` (indexed by node; the others null) from the line
/// elements ending or starting there.
void fillSides(const LoadedSolution& solution, std::vector<SideRotations*>& sides) {
  const auto& elements = solution.model->elements();
  for (int i = 0; i < int(elements.size()); ++i) {
    const LineElement* line = asLine(elements[i]);
    if (!line) continue;
    for (int end : {0, 1}) {
      SideRotations* at = sides[line->endNodes()[end]];
      if (!at) continue;
      std::optional<Eigen::Vector3d>& side = end == 1 ? at->left : at->right;
      if (side) continue;  // the first element in model order on that side
      const auto u = solution.displacementAt(i, end);
      side = Eigen::Vector3d(u[3], u[4], u[5]);
    }
  }
}

}  // namespace

SideRotations rotationsBeside(const LoadedSolution& solution, int node) {
  SideRotations out{node, {}, {}};
  std::vector<SideRotations*> sides(solution.model->nodeCount(), nullptr);
  sides.at(node) = &out;
  fillSides(solution, sides);
  return out;
}

std::vector<SideRotations> hingeRotations(const LoadedSolution& solution) {
  const Model& model = *solution.model;
  // The released ends are found part by part (a pass over every element, which is most of
  // the time when there are none).
  const auto& elements = model.elements();
  const std::vector<int> releasedEnds =
      pickInParts(int(elements.size()), [&](int i, std::vector<int>& out) {
        if (const LineElement* line = asLine(elements[i]))
          for (int end : {0, 1})
            if (line->releases(end)) out.push_back(line->endNodes()[end]);
      });
  std::vector<bool> hinged(model.nodeCount(), false);
  for (int node : releasedEnds) hinged[node] = true;
  std::vector<SideRotations> out;
  for (int n = 0; n < model.nodeCount(); ++n)
    if (hinged[n]) out.push_back({n, {}, {}});
  if (out.empty()) return out;
  std::vector<SideRotations*> sides(model.nodeCount(), nullptr);
  for (SideRotations& s : out) sides[s.node] = &s;
  fillSides(solution, sides);
  return out;
}

std::vector<BeamStation> recoverBeamFields(const LoadedSolution& solution, int perElement) {
  const Model& model = *solution.model;
  std::vector<BeamStation> out;
  const auto& elements = model.elements();
  for (int i = 0; i < int(elements.size()); ++i) {
    const LineElement* beam = asLine(elements[i]);
    if (!beam) continue;
    const ElementVector u = elementValues(*beam, *solution.displacement);
    const ElementSpanLoad q = solution.spanOn(i, *beam);
    const SectionForceSeries forces = beam->sectionForceSeries(u, q);
    const auto [n1, n2] = beam->endNodes();
    const Eigen::Vector3d x1 = model.nodes()[n1], x2 = model.nodes()[n2];
    for (int k = 0; k <= perElement; ++k) {
      BeamStation st;
      st.element = i;
      st.s = double(k) / perElement;
      st.position = x1 + st.s * (x2 - x1);
      st.displacement = beam->displacementAt(u, st.s, q);
      st.forces = forces.at(st.s);
      st.stress = maxNormalStress(beam->section(), st.forces);
      st.shear = maxShearStress(beam->section(), st.forces);
      out.push_back(st);
    }
  }
  return out;
}

}  // namespace beamrotor
