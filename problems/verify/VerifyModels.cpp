#include "problems/verify/VerifyModels.hpp"

namespace beamrotor::verify {

std::shared_ptr<const Section> steelRectangle(double b, double h) {
  return std::make_shared<Section>(
      Section::rectangle("steel", Material::fromEnu("steel", 210e9, 0.3, 7850), b, h));
}

Line planarBeam(Model& model, double L, std::shared_ptr<const Section> section, int n,
                BeamOptions options, bool clampStart) {
  LineSpec spec;
  spec.dofs = DofSet::planar();
  spec.segments.push_back({L, std::move(section), n, 0, options});
  spec.points = {{"start", 0}, {"end", L}};
  const Line line = buildLine(model, spec);
  if (clampStart)
    model.addSupport({"root", line.nodes.front(), {{Dof::ux, 0}, {Dof::uy, 0}, {Dof::rz, 0}}});
  return line;
}

}  // namespace beamrotor::verify
