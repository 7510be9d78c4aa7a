#include "fem/model/Model.hpp"

#include <sstream>
#include <stdexcept>

namespace beamrotor {

int Model::addNode(const Eigen::Vector3d& x) {
  nodes_.push_back(x);
  return int(nodes_.size()) - 1;
}

void Model::nameNode(const std::string& name, int node) {
  if (node < 0 || node >= nodeCount()) throw std::out_of_range("no node " + std::to_string(node));
  auto [it, inserted] = names_.emplace(name, node);
  if (!inserted && it->second != node)
    throw std::invalid_argument("point name '" + name + "' is used twice");
  // A node of several names goes by the first in the names' order.
  auto [first, added] = firstNames_.emplace(node, name);
  if (!added && name < first->second) first->second = name;
}

void Model::nameElement(const std::string& name, int element) {
  if (element < 0 || element >= int(elements_.size()))
    throw std::out_of_range("no element " + std::to_string(element));
  for (const auto& [other, e] : namedElements_)
    if (other == name)
      throw std::invalid_argument("'" + name +
                                  "' names two springs or bearings; give them distinct names");
  namedElements_.emplace_back(name, element);
}

void Model::addMember(const std::string& name, std::vector<int> elements) {
  if (memberNames_.count(name))
    throw std::invalid_argument("member name '" + name + "' is used twice");
  for (int e : elements)
    if (e < 0 || e >= int(elements_.size()))
      throw std::out_of_range("member '" + name + "': no element " + std::to_string(e));
  memberNames_.insert(name);
  members_.emplace_back(name, std::move(elements));
}

int Model::node(const std::string& name) const {
  auto it = names_.find(name);
  if (it == names_.end()) throw std::out_of_range("no point named '" + name + "'");
  return it->second;
}

std::string Model::nameOf(int node) const {
  const auto it = firstNames_.find(node);
  return it == firstNames_.end() ? std::string() : it->second;
}

std::string Model::describe(const NodeDof& d) const {
  std::ostringstream s;
  s << "node " << d.node;
  const std::string name = nameOf(d.node);
  if (!name.empty()) s << " '" << name << "'";
  if (d.node >= 0 && d.node < nodeCount()) {
    const auto& x = nodes_[d.node];
    s << " (x = " << x.x() << ", " << x.y() << ", " << x.z() << ")";
  }
  s << " " << dofName(d.dof);
  return s.str();
}

double Model::size() const {
  if (nodes_.empty()) return 0;
  Eigen::Vector3d lowest = nodes_.front(), highest = nodes_.front();
  for (const Eigen::Vector3d& x : nodes_) {
    lowest = lowest.cwiseMin(x);
    highest = highest.cwiseMax(x);
  }
  return (highest - lowest).maxCoeff();
}

}  // namespace beamrotor
