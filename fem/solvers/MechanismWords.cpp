#include "fem/solvers/MechanismWords.hpp"

#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <sstream>

#include "fem/model/LineElement.hpp"
#include "fem/model/Model.hpp"
#include "fem/solvers/SupportCheck.hpp"

namespace beamrotor {

namespace {

// Motions smaller than this fraction of a mode's largest are rest; parts whose rotations
// differ by less are one part.
constexpr double kSame = 1e-6;
constexpr int kListedParts = 6;
constexpr int kListedDofs = 6;

/// The rigid motion of one line element in one mode: translation of its start node (m) and
/// rotation vector (rad).
struct RigidMotion {
  Eigen::Vector3d t = Eigen::Vector3d::Zero(), w = Eigen::Vector3d::Zero();
};

/// A run of line elements moving as one body in every mode.
struct Part {
  int firstNode = -1, lastNode = -1;
  std::vector<RigidMotion> motion;  ///< per mode, about firstNode
};

class Describer {
 public:
  Describer(const Model& model, const DofMap& dofs, const Mechanism& m)
      : model_(model), dofs_(dofs), m_(m) {
    for (const auto& e : model.elements())
      if (const LineElement* line = asLine(e)) length_ += line->length();
    if (!(length_ > 0)) length_ = 1;
  }

  std::string text() {
    findParts();
    std::ostringstream s;
    s << "the structure is not fully supported: it can move without straining (" << m_.count
      << " independent motion" << (m_.count == 1 ? "" : "s") << "): ";
    int listed = 0;
    std::vector<int> hinges;
    for (std::size_t p = 0; p < parts_.size(); ++p) {
      const std::string how = motionWords(parts_[p]);
      if (how.empty()) continue;
      if (listed++ >= kListedParts) continue;
      s << (listed > 1 ? "; " : "") << "the beams from " << place(parts_[p].firstNode) << " to "
        << place(parts_[p].lastNode) << " " << how;
      for (int node : {parts_[p].firstNode, parts_[p].lastNode})
        if (hinged(node) && std::find(hinges.begin(), hinges.end(), node) == hinges.end())
          hinges.push_back(node);
    }
    if (listed > kListedParts) s << "; and " << listed - kListedParts << " more parts";
    const std::string off = offLineDofs(listed == 0);
    if (!off.empty()) s << (listed ? "; also " : "") << off;
    if (!hinges.empty()) {
      std::sort(hinges.begin(), hinges.end());
      s << ". The hinge" << (hinges.size() > 1 ? "s" : "") << " at ";
      for (std::size_t i = 0; i < hinges.size(); ++i)
        s << (i ? (i + 1 == hinges.size() ? " and " : ", ") : "") << place(hinges[i]);
      s << (hinges.size() > 1 ? " let" : " lets") << " it move. Add a support or a spring "
        << "that holds it, or remove a hinge.";
    } else {
      s << ". Add a support or a spring that holds it.";
    }
    return s.str();
  }

 private:
  /// A mode's value at (node, d); 0 where the node has no free such dof.
  double value(int mode, int node, Dof d) const {
    const int eq = dofs_.equation(node, d);
    return dofs_.isFree(eq) ? m_.modes[mode][eq] : 0.0;
  }
  Eigen::Vector3d translation(int mode, int node) const {
    return {value(mode, node, Dof::ux), value(mode, node, Dof::uy), value(mode, node, Dof::uz)};
  }
  Eigen::Vector3d rotation(int mode, int node) const {
    return {value(mode, node, Dof::rx), value(mode, node, Dof::ry), value(mode, node, Dof::rz)};
  }

  /// The element's rigid motion: the rotation across its axis from its ends' translations,
  /// the twist from a node it does not release.
  RigidMotion motionOf(int mode, const LineElement& line) const {
    const auto [a, b] = line.endNodes();
    const Eigen::Vector3d d = model_.nodes()[b] - model_.nodes()[a];
    RigidMotion r;
    r.t = translation(mode, a);
    r.w = d.cross(translation(mode, b) - r.t) / d.squaredNorm();
    const Eigen::Vector3d axis = d.normalized();
    const int twistNode = line.releases(0) ? b : a;
    r.w += axis.dot(rotation(mode, twistNode)) * axis;
    return r;
  }

  void findParts() {
    const int modes = int(m_.modes.size());
    // Each mode's size: its largest translation or rotation times the line's length.
    std::vector<double> size(modes, 0.0);
    for (const auto& e : model_.elements())
      if (const LineElement* line = asLine(e))
        for (int k = 0; k < modes; ++k) {
          const RigidMotion r = motionOf(k, *line);
          size[k] = std::max({size[k], r.t.norm(), r.w.norm() * length_});
        }
    for (int k = 0; k < modes; ++k)
      for (int eq = 0; eq < dofs_.freeCount(); ++eq)
        if (!isRotation(dofs_.dofOf(eq).dof))
          size[k] = std::max(size[k], std::abs(m_.modes[k][eq]));
    size_ = size;
    int previousEnd = -1;
    std::vector<RigidMotion> previous;
    for (const auto& e : model_.elements()) {
      const LineElement* line = asLine(e);
      if (!line) continue;
      const auto [a, b] = line->endNodes();
      std::vector<RigidMotion> motion(modes);
      bool same = a == previousEnd && !parts_.empty();
      for (int k = 0; k < modes; ++k) {
        motion[k] = motionOf(k, *line);
        if (same && (motion[k].w - previous[k].w).norm() * length_ > kSame * size[k]) same = false;
      }
      if (same) {
        parts_.back().lastNode = b;
      } else {
        parts_.push_back({a, b, motion});
      }
      previous = motion;
      previousEnd = b;
    }
  }

  bool hinged(int node) const {
    for (const auto& e : model_.elements())
      if (const LineElement* line = asLine(e))
        for (int end : {0, 1})
          if (line->endNodes()[end] == node && line->releases(end)) return true;
    return false;
  }

  /// "x = 1.2 m ('h1')" for a line along x, "(1, 2, 0) m ('h1')" otherwise.
  std::string place(const Eigen::Vector3d& x, int node) const {
    std::ostringstream s;
    if (std::abs(x.y()) <= 1e-12 * length_ && std::abs(x.z()) <= 1e-12 * length_)
      s << "x = " << x.x() << " m";
    else
      s << "(" << x.x() << ", " << x.y() << ", " << x.z() << ") m";
    const std::string name = node >= 0 ? model_.nameOf(node) : "";
    if (!name.empty()) s << " ('" << name << "')";
    return s.str();
  }
  std::string place(int node) const { return place(model_.nodes()[node], node); }

  /// The nearest node to x when within kSame of the line's length, else -1.
  int nodeAt(const Eigen::Vector3d& x) const {
    int best = -1;
    double distance = kSame * length_;
    for (int n = 0; n < model_.nodeCount(); ++n) {
      const double dn = (model_.nodes()[n] - x).norm();
      if (dn <= distance) best = n, distance = dn;
    }
    return best;
  }

  static std::string direction(const Eigen::Vector3d& v) {
    const Eigen::Vector3d u = v.normalized();
    for (int k = 0; k < 3; ++k)
      if (std::abs(u[k]) > 1 - 1e-9) return std::string(1, char('x' + k));
    std::ostringstream s;
    s << "(" << u.x() << ", " << u.y() << ", " << u.z() << ")";
    return s.str();
  }

  /// How a part moves over the modes; empty when it rests.
  std::string motionWords(const Part& p) const {
    const int modes = int(p.motion.size());
    Eigen::MatrixXd span(6, modes);  // columns: (t, w L) per mode, relative to its size
    for (int k = 0; k < modes; ++k) {
      const double size = size_[k] > 0 ? size_[k] : 1;
      span.col(k) << p.motion[k].t / size, p.motion[k].w * length_ / size;
    }
    const Eigen::JacobiSVD<Eigen::MatrixXd> svd(span, Eigen::ComputeThinU);
    int rank = 0;
    for (int k = 0; k < svd.singularValues().size(); ++k) rank += svd.singularValues()[k] > kSame;
    if (rank == 0) return "";
    const Eigen::MatrixXd basis = svd.matrixU().leftCols(rank);
    const Eigen::Vector3d origin = model_.nodes()[p.firstNode];
    if (rank == 1) {
      const Eigen::Vector3d t = basis.col(0).head<3>(), w = basis.col(0).tail<3>() / length_;
      // A global axis also names the dof that moves: "along x (ux)", "about ... (rz)".
      const auto dof = [](char kind, const std::string& axis) {
        return axis.size() == 1 ? " (" + std::string(1, kind) + axis + ")"
                                : " (axis along " + axis + ")";
      };
      if (w.norm() * length_ <= kSame * t.norm())
        return "translate along " + direction(t) + dof('u', direction(t));
      const Eigen::Vector3d centre = origin + w.cross(t) / w.squaredNorm();
      const int node = nodeAt(centre);
      return "turn about " + (node >= 0 ? place(node) : place(centre, -1)) + dof('r', direction(w));
    }
    // Several motions: which pure translations and rotation axes the span holds.
    const auto holds = [&](const Eigen::Matrix<double, 6, 1>& v) {
      return (v - basis * (basis.transpose() * v)).norm() <= 1e-6;
    };
    std::vector<std::string> moves, turns;
    for (int k = 0; k < 3; ++k) {
      Eigen::Matrix<double, 6, 1> v = Eigen::Matrix<double, 6, 1>::Zero();
      v[k] = 1;
      if (holds(v)) moves.push_back(std::string(1, char('x' + k)));
      // A turn about axis k through some point: w along k, any translation with it.
      Eigen::MatrixXd wRows = basis.bottomRows(3);
      const Eigen::Vector3d e = Eigen::Vector3d::Unit(k);
      const Eigen::Vector3d projected = wRows * (wRows.completeOrthogonalDecomposition().solve(e));
      if ((projected - e).norm() <= 1e-6) turns.push_back(std::string(1, char('x' + k)));
    }
    std::ostringstream s;
    s << "move as a free body (" << rank << " motions):";
    const auto list = [&](const std::vector<std::string>& v) {
      std::string out;
      for (std::size_t i = 0; i < v.size(); ++i)
        out += (i ? (i + 1 == v.size() ? " and " : ", ") : "") + v[i];
      return out;
    };
    if (!moves.empty()) s << " translating along " << list(moves);
    if (!turns.empty()) s << (moves.empty() ? "" : ",") << " turning about " << list(turns);
    return s.str();
  }

  /// Moving dofs at nodes of no line element (all of them when no part of a line moves).
  std::string offLineDofs(bool all) const {
    std::vector<bool> onLine(model_.nodeCount(), false);
    if (!all)
      for (const auto& e : model_.elements())
        if (const LineElement* line = asLine(e))
          for (int n : line->endNodes()) onLine[n] = true;
    std::vector<NodeDof> off;
    for (const NodeDof& d : m_.moving)
      if (!onLine[d.node]) off.push_back(d);
    if (off.empty()) return "";
    std::ostringstream s;
    s << off.size() << " dof(s) nothing holds: ";
    for (int i = 0; i < int(off.size()) && i < kListedDofs; ++i)
      s << (i ? ", " : "") << model_.describe(off[i]);
    if (int(off.size()) > kListedDofs) s << ", ... and " << off.size() - kListedDofs << " more";
    return s.str();
  }

  const Model& model_;
  const DofMap& dofs_;
  const Mechanism& m_;
  double length_ = 0;
  std::vector<double> size_;
  std::vector<Part> parts_;
};

}  // namespace

std::string describeMechanism(const Model& model, const DofMap& dofs, const Mechanism& mechanism) {
  return Describer(model, dofs, mechanism).text();
}

}  // namespace beamrotor
