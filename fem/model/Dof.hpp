// Degrees of freedom: the six kinds a node can carry, and the sets a model uses.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <optional>
#include <string>
#include <string_view>

namespace beamrotor {

/// The kind of a nodal degree of freedom, global frame: translations ux, uy, uz (m) and
/// rotations rx, ry, rz (rad, right-hand rule about the global axes).
enum class Dof : std::uint8_t { ux = 0, uy, uz, rx, ry, rz };

inline constexpr int kDofKinds = 6;
inline constexpr std::array<Dof, kDofKinds> kAllDofs{Dof::ux, Dof::uy, Dof::uz,
                                                     Dof::rx, Dof::ry, Dof::rz};

/// "ux" ... "rz".
std::string_view dofName(Dof d);
/// Inverse of dofName; nullopt for anything else.
std::optional<Dof> parseDof(std::string_view name);
inline constexpr int dofIndex(Dof d) {
  return static_cast<int>(d);
}
inline constexpr bool isRotation(Dof d) {
  return dofIndex(d) >= 3;
}

/// A set of dof kinds, e.g. the ones every node of a planar model carries.
class DofSet {
 public:
  constexpr DofSet() = default;
  constexpr DofSet(std::initializer_list<Dof> dofs) {
    for (Dof d : dofs) bits_ |= bit(d);
  }
  constexpr bool contains(Dof d) const { return (bits_ & bit(d)) != 0; }
  constexpr int size() const {
    int n = 0;
    for (Dof d : kAllDofs) n += contains(d) ? 1 : 0;
    return n;
  }
  constexpr bool operator==(const DofSet&) const = default;
  /// This set and d.
  constexpr DofSet with(Dof d) const {
    DofSet out = *this;
    out.bits_ |= bit(d);
    return out;
  }

  /// Axial and bending in the x-y plane: ux, uy, rz.
  static constexpr DofSet planar() { return {Dof::ux, Dof::uy, Dof::rz}; }
  /// All six: 3D frames.
  static constexpr DofSet frame3d() {
    return {Dof::ux, Dof::uy, Dof::uz, Dof::rx, Dof::ry, Dof::rz};
  }
  /// Lateral rotor dynamics with the shaft along x: uy, uz, ry, rz (two bending planes).
  static constexpr DofSet lateral() { return {Dof::uy, Dof::uz, Dof::ry, Dof::rz}; }
  /// A shaft train in torsion with the shafts along x: the twist rx alone.
  static constexpr DofSet torsion() { return {Dof::rx}; }

 private:
  static constexpr std::uint8_t bit(Dof d) { return std::uint8_t(1u << dofIndex(d)); }
  std::uint8_t bits_ = 0;
};

/// One degree of freedom of one node.
struct NodeDof {
  int node = -1;
  Dof dof = Dof::ux;
  bool operator==(const NodeDof&) const = default;
};

/// "node 3 uy", or "point 'left' uy" when the node has a name (see Model::describe).
std::string toString(const NodeDof& d);

/// One of an element's dofs in a byte: which of its (at most two) nodes, and which kind.
inline constexpr std::uint8_t elementDofCode(int end, Dof d) {
  return std::uint8_t(8 * end + dofIndex(d));
}

/// The dofs an element couples, in the order of its matrices: its two node numbers and one
/// code for each dof (elementDofCode). A beam's codes are shared by every beam like it, so a
/// beam keeps 8 bytes of dofs where a list of NodeDofs took 96 (10^6 beams: 88 MB). Read
/// through it, a dof is a NodeDof made on the spot (a value, not a reference).
class ElementDofs {
 public:
  ElementDofs(std::array<int, 2> nodes, const std::uint8_t* codes, int count)
      : nodes_(nodes), codes_(codes), count_(count) {}
  std::size_t size() const { return std::size_t(count_); }
  bool empty() const { return count_ == 0; }
  NodeDof operator[](std::size_t k) const { return decode(nodes_, codes_[k]); }

  class iterator {
   public:
    using iterator_category = std::input_iterator_tag;  // its dofs are values
    using iterator_concept = std::forward_iterator_tag;
    using value_type = NodeDof;
    using difference_type = std::ptrdiff_t;
    using pointer = void;
    using reference = NodeDof;
    iterator() = default;
    iterator(std::array<int, 2> nodes, const std::uint8_t* code) : nodes_(nodes), code_(code) {}
    NodeDof operator*() const { return decode(nodes_, *code_); }
    iterator& operator++() {
      ++code_;
      return *this;
    }
    iterator operator++(int) {
      iterator old = *this;
      ++code_;
      return old;
    }
    bool operator==(const iterator& o) const { return code_ == o.code_; }
    difference_type operator-(const iterator& o) const { return code_ - o.code_; }

   private:
    std::array<int, 2> nodes_{};
    const std::uint8_t* code_ = nullptr;
  };
  iterator begin() const { return {nodes_, codes_}; }
  iterator end() const { return {nodes_, codes_ + count_}; }

 private:
  static NodeDof decode(const std::array<int, 2>& nodes, std::uint8_t code) {
    return {nodes[code >> 3], Dof(code & 7)};
  }
  std::array<int, 2> nodes_;
  const std::uint8_t* codes_;
  int count_;
};

}  // namespace beamrotor
