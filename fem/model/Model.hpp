// The model: nodes, elements, supports and nodal loads. A plain container that the mesh
// builders and the deck reader fill and the analyses read.
#pragma once

#include <Eigen/Dense>
#include <limits>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "fem/model/Dof.hpp"
#include "fem/model/Element.hpp"

namespace beamrotor {

/// One constrained dof of a support: fixed (value 0) or prescribed (value in m or rad).
struct PrescribedDof {
  Dof dof = Dof::ux;
  double value = 0;
};

/// A named support at one node; its reaction is reported under its name.
struct Support {
  std::string name;
  int node = -1;
  std::vector<PrescribedDof> dofs;
};

/// A one-dof contact with the fixed frame: the dof's value must stay within [lower, upper]
/// (m or rad; either bound may be infinite). A rotation stop is both bounds on a rotation,
/// a unilateral support one bound at 0 on a translation, a gap one bound at the gap.
struct ContactConstraint {
  std::string name;
  int node = -1;
  Dof dof = Dof::uy;
  double lower = -std::numeric_limits<double>::infinity();
  double upper = std::numeric_limits<double>::infinity();
};

/// A rigid tie: the dofs `dofs` of node `slave` follow node `master` as one rigid body, the
/// translations as u_s = u_m + theta_m x (x_s - x_m) and the rotations as theta_s = theta_m
/// (each listed component). Rigid links, member end offsets and diaphragms are made of these;
/// the statics eliminate the slave dofs exactly (fem/assembly/RigidTies.hpp), no spring.
struct RigidTie {
  std::string name;
  int master = -1;
  int slave = -1;
  std::vector<Dof> dofs;
};

/// A concentrated force (N) or moment (N m) at a node, global frame.
struct NodalLoad {
  int node = -1;
  Dof dof = Dof::uy;
  double value = 0;
};

class Model {
 public:
  /// Adds a node at x (m, global frame); returns its index.
  int addNode(const Eigen::Vector3d& x);
  /// Gives node a name ("left", "middle"); names are unique.
  void nameNode(const std::string& name, int node);
  /// The node of a name; throws std::out_of_range naming the missing point.
  int node(const std::string& name) const;
  /// The node's name, or empty.
  std::string nameOf(int node) const;

  template <class E, class... Args>
  E& add(Args&&... args) {
    auto e = std::make_unique<E>(std::forward<Args>(args)...);
    E& ref = *e;
    elements_.push_back(std::move(e));
    return ref;
  }
  void addElement(std::unique_ptr<Element> e) { elements_.push_back(std::move(e)); }
  void addSupport(Support s) { supports_.push_back(std::move(s)); }
  void addLoad(const NodalLoad& l) { loads_.push_back(l); }
  void addContact(ContactConstraint c) { contacts_.push_back(std::move(c)); }
  void addRigidTie(RigidTie t) { ties_.push_back(std::move(t)); }
  /// Names an element that acts like a support (a spring, a bearing), so that the force it
  /// exerts on the structure is reported under its name. Names are unique among them.
  void nameElement(const std::string& name, int element);
  /// Names a member: a chain of line elements (indices into elements(), from its start to
  /// its end) that output reports as one piece, e.g. a frame's column. Names are unique.
  void addMember(const std::string& name, std::vector<int> elements);

  const std::vector<Eigen::Vector3d>& nodes() const { return nodes_; }
  const std::vector<std::unique_ptr<Element>>& elements() const { return elements_; }
  const std::vector<Support>& supports() const { return supports_; }
  const std::vector<NodalLoad>& loads() const { return loads_; }
  const std::vector<ContactConstraint>& contacts() const { return contacts_; }
  const std::vector<RigidTie>& rigidTies() const { return ties_; }
  const std::map<std::string, int>& namedNodes() const { return names_; }
  /// The named elements in the order they were named: name and element index.
  const std::vector<std::pair<std::string, int>>& namedElements() const { return namedElements_; }
  /// The members in the order they were added: name and element indices.
  const std::vector<std::pair<std::string, std::vector<int>>>& members() const { return members_; }
  int nodeCount() const { return int(nodes_.size()); }
  /// The largest extent of the nodes along x, y or z (m); 0 when they all sit at one place.
  double size() const;

  /// "node 4 (x = 0.575, 0, 0) uy", with the point name when there is one; for messages.
  std::string describe(const NodeDof& d) const;

 private:
  std::vector<Eigen::Vector3d> nodes_;
  std::vector<std::unique_ptr<Element>> elements_;
  std::vector<Support> supports_;
  std::vector<NodalLoad> loads_;
  std::vector<ContactConstraint> contacts_;
  std::vector<RigidTie> ties_;
  std::map<std::string, int> names_;
  std::map<int, std::string> firstNames_;  ///< each named node's first name (nameOf)
  std::vector<std::pair<std::string, std::vector<int>>> members_;
  std::set<std::string> memberNames_;
  std::vector<std::pair<std::string, int>> namedElements_;
};

}  // namespace beamrotor
