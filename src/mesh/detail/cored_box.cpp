#include "stcontact/mesh/detail/cored_box.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "stcontact/mesh/detail/box_grid.hpp"
#include "stcontact/mesh/detail/prism_split.hpp"

namespace stc::detail {
namespace {

using Tets = std::vector<std::array<int, 4>>;
const Eigen::Vector3d kPole(0.0, 0.0, -1.0);

// The core grid's outer surface ‖x − P‖_∞ = 1: its nodes, numbered 0..n_s − 1 in the order of their
// grid ids, and its triangles (faces of the grid's tetrahedra on the four sides and the top; the
// bottom z = −1 is the body's boundary, not a shell's), each as sorted surface numbers.
struct CoreSurface {
  std::vector<int> nodes;
  std::vector<std::array<int, 3>> triangles;
};

bool onOneOuterFace(const BoxGrid& grid, const std::array<int, 3>& t) {
  const int side = 2 * grid.divisions();
  const auto all = [&](auto test) { return std::all_of(t.begin(), t.end(), test); };
  return all([&](int n) { return grid.column(n) == 0; }) || all([&](int n) { return grid.column(n) == side; }) ||
         all([&](int n) { return grid.row(n) == 0; }) || all([&](int n) { return grid.row(n) == side; }) ||
         all([&](int n) { return grid.layer(n) == grid.divisions(); });
}

CoreSurface outerSurface(const BoxGrid& grid, const TetMesh& core) {
  CoreSurface surface;
  std::vector<int> number(grid.numNodes(), -1);
  for (int n = 0; n < grid.numNodes(); ++n)
    if (grid.poleDistance(n) == 1.0) {
      number[n] = static_cast<int>(surface.nodes.size());
      surface.nodes.push_back(n);
    }
  for (const auto& t : boundaryTriangles(core)) {
    if (!onOneOuterFace(grid, t)) continue;
    std::array<int, 3> q{number[t[0]], number[t[1]], number[t[2]]};
    std::sort(q.begin(), q.end());
    surface.triangles.push_back(q);
  }
  return surface;
}

// The layout of the cored box: core grid (m cells along s0), L shell layers, the outer grid of
// D = 2m + 1 divisions without its hole ‖x − P‖_∞ < s1 = m / D (s1 < 1/2 keeps every kink of the
// ball map but |x| = |y| out of the inner part; |x| = |y| is made of element faces there).
class Layout {
 public:
  Layout(int m, double core)
      : core_(m), outer_(2 * m + 1), s0_(core), s1_(double(m) / (2 * m + 1)),
        shells_(std::max(1, static_cast<int>(std::ceil(std::log(s1_ / s0_) / std::log1p(1.0 / m))))) {}

  const BoxGrid& core() const { return core_; }
  const BoxGrid& outer() const { return outer_; }
  int shells() const { return shells_; }  // L: layer 0 is the core's surface, layer L the hole's
  double layerScale(int l) const { return s0_ * std::pow(s1_ / s0_, double(l) / shells_); }
  double coreScale() const { return s0_; }
  // The outer grid node on the hole's surface that matches core surface node n (both at s1 (x_n − P)).
  int outerMatch(int n) const {
    const int shift = outer_.divisions() - core_.divisions();
    return outer_.id(core_.column(n) + shift, core_.row(n) + shift, core_.layer(n));
  }
  bool outerKept(int n) const { return outer_.poleDistance(n) * outer_.divisions() >= core_.divisions() - 0.5; }

 private:
  BoxGrid core_, outer_;
  double s0_, s1_;
  int shells_;
};

}  // namespace

// Nodes: the core grid's (numbered as BoxGrid(m)), then layers 1..L − 1 (n_s each), then the outer
// grid's kept nodes in the order of their ids; layer L is made of outer nodes.
TetMesh coredBox(int divisions, double core) {
  const Layout layout(divisions, core);
  const BoxGrid& inner = layout.core();
  const BoxGrid& outer = layout.outer();
  TetMesh coreMesh;
  coreMesh.tets = boxTetrahedra(inner);
  coreMesh.nodes.resize(3, inner.numNodes());
  for (int n = 0; n < inner.numNodes(); ++n) coreMesh.nodes.col(n) = inner.reference(n);
  const CoreSurface surface = outerSurface(inner, coreMesh);
  const int n_core = inner.numNodes(), n_surface = static_cast<int>(surface.nodes.size());
  const int first_outer = n_core + (layout.shells() - 1) * n_surface;

  std::vector<int> outerId(outer.numNodes(), -1);
  int next = first_outer;
  for (int n = 0; n < outer.numNodes(); ++n)
    if (layout.outerKept(n)) outerId[n] = next++;

  Eigen::Matrix3Xd nodes(3, next);
  for (int n = 0; n < n_core; ++n) nodes.col(n) = kPole + layout.coreScale() * (coreMesh.nodes.col(n) - kPole);
  for (int l = 1; l < layout.shells(); ++l)
    for (int q = 0; q < n_surface; ++q)
      nodes.col(n_core + (l - 1) * n_surface + q) =
          kPole + layout.layerScale(l) * (inner.reference(surface.nodes[q]) - kPole);
  for (int n = 0; n < outer.numNodes(); ++n)
    if (outerId[n] >= 0) nodes.col(outerId[n]) = outer.reference(n);

  Tets tets;
  for (int e = 0; e < coreMesh.numElements(); ++e)
    tets.push_back({coreMesh.tets(0, e), coreMesh.tets(1, e), coreMesh.tets(2, e), coreMesh.tets(3, e)});
  const auto id = [&](int q, int l) {
    if (l == 0) return surface.nodes[q];
    if (l == layout.shells()) return outerId[layout.outerMatch(surface.nodes[q])];
    return n_core + (l - 1) * n_surface + q;
  };
  for (int l = 0; l < layout.shells(); ++l)
    for (const auto& t : surface.triangles)
      splitPrism({id(t[0], l), id(t[1], l), id(t[2], l)}, {id(t[0], l + 1), id(t[1], l + 1), id(t[2], l + 1)}, tets);
  const Eigen::Matrix4Xi outerTets = boxTetrahedra(outer, inner.divisions());
  for (int e = 0; e < outerTets.cols(); ++e) {
    const auto node = [&](int a) { return outerId[outerTets(a, e)]; };
    tets.push_back({node(0), node(1), node(2), node(3)});
  }

  TetMesh box;
  box.nodes = std::move(nodes);
  box.tets.resize(4, static_cast<Eigen::Index>(tets.size()));
  for (std::size_t e = 0; e < tets.size(); ++e) box.tets.col(e) << tets[e][0], tets[e][1], tets[e][2], tets[e][3];
  for (int e = 0; e < box.numElements(); ++e)  // the prism split does not orient
    if (box.sixSignedVolume(e) < 0.0) std::swap(box.tets(2, e), box.tets(3, e));
  return box;
}

}  // namespace stc::detail
