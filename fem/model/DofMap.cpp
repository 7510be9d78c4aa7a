#include "fem/model/DofMap.hpp"

#include <stdexcept>

#include "fem/model/Model.hpp"

namespace beamrotor {

namespace {
constexpr int kAbsent = -1;
constexpr int kPresent = -2;      // touched by an element, not yet numbered
constexpr int kConstrained = -3;  // held by a support, not yet numbered
}  // namespace

DofMap::DofMap(const Model& model) {
  // 1. Mark what exists: every dof an element touches, then the supported ones.
  slots_.assign(model.nodeCount(), {kAbsent, kAbsent, kAbsent, kAbsent, kAbsent, kAbsent});
  for (const auto& e : model.elements())
    for (const NodeDof& d : e->dofs()) slots_.at(d.node)[dofIndex(d.dof)] = kPresent;
  // A tie's master moves its slave: it carries every dof its slave does (a member end offset
  // hangs a member from a joint that no element touches). And a slave follows its master in
  // each tied dof the master carries (a bracket's tip that no element touches still takes a
  // load). Repeated until nothing changes: along a chain of ties the dofs pass link by link.
  for (bool changed = !model.rigidTies().empty(); changed;) {
    changed = false;
    const auto mark = [&](int node, int k) {
      if (slots_.at(node)[k] == kPresent) return;
      slots_[node][k] = kPresent;
      changed = true;
    };
    for (const RigidTie& t : model.rigidTies())
      for (int k = 0; k < kDofKinds; ++k)
        if (slots_.at(t.slave)[k] == kPresent) mark(t.master, k);
    for (const RigidTie& t : model.rigidTies())
      for (Dof d : t.dofs)
        if (slots_.at(t.master)[dofIndex(d)] == kPresent) mark(t.slave, dofIndex(d));
  }
  for (const Support& s : model.supports())
    for (const PrescribedDof& p : s.dofs) {
      int& slot = slots_.at(s.node)[dofIndex(p.dof)];
      // A support on a dof no element touches constrains nothing; it still gets a number so
      // that its (zero) reaction can be reported.
      if (slot == kConstrained)
        throw std::invalid_argument("support '" + s.name + "' constrains " +
                                    model.describe({s.node, p.dof}) + " a second time");
      slot = kConstrained;
    }

  for (const ContactConstraint& c : model.contacts()) {
    const int slot = slots_.at(c.node)[dofIndex(c.dof)];
    if (slot == kAbsent)
      throw std::invalid_argument("contact '" + c.name + "' acts on " +
                                  model.describe({c.node, c.dof}) + ", which no element carries");
    if (slot == kConstrained)
      throw std::invalid_argument("contact '" + c.name + "' acts on " +
                                  model.describe({c.node, c.dof}) +
                                  ", which a support already holds");
  }

  // 2. Number free dofs node by node, then constrained ones (the list sized once: pushed one
  //    by one, its capacity would end up to twice its size, 16 MB more at 10^6 elements).
  std::size_t count = 0;
  for (const auto& node : slots_)
    for (int slot : node) count += slot != kAbsent;
  dofs_.reserve(count);
  for (int pass = 0; pass < 2; ++pass) {
    const int wanted = pass == 0 ? kPresent : kConstrained;
    for (int n = 0; n < int(slots_.size()); ++n)
      for (Dof d : kAllDofs) {
        int& slot = slots_[n][dofIndex(d)];
        if (slot != wanted) continue;
        slot = int(dofs_.size());
        dofs_.push_back({n, d});
      }
    if (pass == 0) freeCount_ = int(dofs_.size());
  }
}

std::vector<int> DofMap::freeNodes() const {
  std::vector<int> nodes(static_cast<std::size_t>(freeCount_));
  for (int e = 0; e < freeCount_; ++e) nodes[std::size_t(e)] = dofs_[std::size_t(e)].node;
  return nodes;
}

}  // namespace beamrotor
