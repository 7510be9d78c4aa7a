#include "fem/assembly/Recovery.hpp"

#include "fem/model/ShearStress.hpp"

namespace beamrotor {

std::vector<BeamStation> recoverBeamFields(const Model& model, const NodalField& displacement,
                                           int perElement) {
  std::vector<BeamStation> out;
  const auto& elements = model.elements();
  for (int i = 0; i < int(elements.size()); ++i) {
    const auto* beam = dynamic_cast<const LineElement*>(elements[i].get());
    if (!beam) continue;
    const auto d = beam->dofs();
    ElementVector u(d.size());
    for (int a = 0; a < int(d.size()); ++a) u[a] = displacement(d[a].node, dofIndex(d[a].dof));
    const auto [n1, n2] = beam->endNodes();
    const Eigen::Vector3d x1 = model.nodes()[n1], x2 = model.nodes()[n2];
    for (int k = 0; k <= perElement; ++k) {
      BeamStation st;
      st.element = i;
      st.s = double(k) / perElement;
      st.position = x1 + st.s * (x2 - x1);
      st.forces = beam->sectionForces(u, st.s);
      st.stress = maxNormalStress(beam->section(), st.forces);
      st.shear = maxShearStress(beam->section(), st.forces);
      out.push_back(st);
    }
  }
  return out;
}

}  // namespace beamrotor
