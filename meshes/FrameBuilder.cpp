#include "meshes/FrameBuilder.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace beamrotor {

namespace {

/// Fractions of a member closer than this are one place (relative to its length).
constexpr double kFractionTolerance = 1e-12;

/// The unit part of `reference` perpendicular to unit vector `ex`; throws when none is left.
Eigen::Vector3d perpendicularPart(const Eigen::Vector3d& reference, const Eigen::Vector3d& ex,
                                  const char* what) {
  const double n = reference.norm();
  if (!(n > 0) || !std::isfinite(n))
    throw std::invalid_argument(std::string(what) + " reference must be a non-zero vector");
  const Eigen::Vector3d r = reference / n;
  const Eigen::Vector3d p = r - r.dot(ex) * ex;
  if (p.norm() < 1e-9)
    throw std::invalid_argument(std::string(what) +
                                " reference is parallel to the member; give a direction across it");
  return p.normalized();
}

}  // namespace

Eigen::Matrix3d memberAxes(const Eigen::Vector3d& axis, const MemberOrientation& orientation) {
  const double L = axis.norm();
  if (!(L > 0)) throw std::invalid_argument("member of zero length");
  const Eigen::Vector3d ex = axis / L;
  Eigen::Vector3d ez;
  if (orientation.zReference) {
    ez = perpendicularPart(*orientation.zReference, ex, "the local z");
  } else if (orientation.yReference) {
    ez = ex.cross(perpendicularPart(*orientation.yReference, ex, "the local y"));
  } else if (std::abs(ex.z()) > 1 - 1e-9) {
    ez = ex.cross(Eigen::Vector3d::UnitY());  // along global z: local y = global +y
  } else {
    ez = perpendicularPart(Eigen::Vector3d::UnitZ(), ex, "the local z");
  }
  Eigen::Vector3d ey = ez.cross(ex);
  const double c = std::cos(orientation.roll), s = std::sin(orientation.roll);
  const Eigen::Vector3d y = c * ey + s * ez, z = -s * ey + c * ez;
  Eigen::Matrix3d R;
  R.row(0) = ex;
  R.row(1) = y;
  R.row(2) = z;
  return R;
}

FrameMesh buildFrame(Model& model, const FrameSpec& spec) {
  FrameMesh frame;
  // 1. Joints, which must be apart.
  double extent = 0;
  for (const FrameJoint& j : spec.joints) extent = std::max(extent, j.x.cwiseAbs().maxCoeff());
  const double tol = 1e-12 * std::max(1.0, extent);
  for (std::size_t j = 0; j < spec.joints.size(); ++j) {
    for (std::size_t k = 0; k < j; ++k)
      if ((spec.joints[j].x - spec.joints[k].x).norm() <= tol)
        throw std::invalid_argument("joint '" + spec.joints[j].name + "' lies on joint '" +
                                    spec.joints[k].name + "'");
    frame.jointNodes.push_back(model.addNode(spec.joints[j].x));
    model.nameNode(spec.joints[j].name, frame.jointNodes.back());
  }

  // 2. Members, cut at their stations.
  for (std::size_t m = 0; m < spec.members.size(); ++m) {
    const FrameMember& member = spec.members[m];
    const int joints = int(spec.joints.size());
    if (member.from < 0 || member.from >= joints || member.to < 0 || member.to >= joints)
      throw std::invalid_argument("member joint out of range");
    const Eigen::Vector3d x1 = spec.joints[member.from].x, x2 = spec.joints[member.to].x;
    const double L = (x2 - x1).norm();
    if (!(L > tol)) throw std::invalid_argument("member of zero length");
    const Eigen::Matrix3d R = memberAxes(x2 - x1, member.orientation);
    Segment mesh = member.mesh;
    mesh.length = L;

    std::vector<double> cuts{0, 1};
    std::vector<std::pair<double, int>> inside;  // joints on this member: fraction, node
    for (std::size_t j = 0; j < spec.joints.size(); ++j)
      if (spec.joints[j].member == int(m)) {
        cuts.push_back(spec.joints[j].fraction);
        inside.emplace_back(spec.joints[j].fraction, frame.jointNodes[j]);
      }
    for (const MemberStation& s : spec.stations)
      if (s.member == int(m)) {
        if (!(s.fraction >= 0 && s.fraction <= 1))
          throw std::invalid_argument("station '" + s.name + "' lies outside its member");
        cuts.push_back(s.fraction);
      }
    std::sort(cuts.begin(), cuts.end());
    cuts.erase(std::unique(cuts.begin(), cuts.end(),
                           [](double a, double b) { return b - a <= kFractionTolerance; }),
               cuts.end());
    cuts.back() = 1;

    std::vector<Beam*> beams;
    std::vector<double> fractions{0};
    int from = frame.jointNodes[member.from];
    for (std::size_t c = 0; c + 1 < cuts.size(); ++c) {
      const double piece = cuts[c + 1] - cuts[c];
      const int n = elementsFor(mesh, piece * L);
      for (int e = 1; e <= n; ++e) {
        const double f = e == n ? cuts[c + 1] : cuts[c] + piece * e / n;
        int to = -1;
        if (f == 1) to = frame.jointNodes[member.to];
        for (const auto& [fraction, node] : inside)
          if (e == n && std::abs(fraction - f) <= kFractionTolerance) to = node;
        if (to < 0) to = model.addNode(x1 + f * (x2 - x1));
        beams.push_back(&model.add<Beam>(from, model.nodes()[from], to, model.nodes()[to],
                                         mesh.section, spec.dofs, mesh.options,
                                         Eigen::Vector3d(R.row(2).transpose())));
        fractions.push_back(f);
        from = to;
      }
    }
    for (int end = 0; end < 2; ++end)
      for (Dof d : member.releases[end])
        (end == 0 ? beams.front() : beams.back())->release(end, d);
    frame.memberBeams.push_back(std::move(beams));
    frame.memberFractions.push_back(std::move(fractions));
  }

  // 3. Name the stations: each goes to the member's node nearest its fraction.
  for (const MemberStation& s : spec.stations) {
    if (s.member < 0 || s.member >= int(spec.members.size()))
      throw std::invalid_argument("station '" + s.name + "' on a member out of range");
    const std::vector<double>& f = frame.memberFractions[s.member];
    const auto it = std::min_element(f.begin(), f.end(), [&](double a, double b) {
      return std::abs(a - s.fraction) < std::abs(b - s.fraction);
    });
    const std::size_t k = it - f.begin();
    const std::vector<Beam*>& beams = frame.memberBeams[s.member];
    const int node = k < beams.size() ? beams[k]->endNodes()[0] : beams.back()->endNodes()[1];
    model.nameNode(s.name, node);
  }
  return frame;
}

}  // namespace beamrotor
