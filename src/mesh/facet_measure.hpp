#pragma once
// Measures of boundary facets: an edge's length (2D meshes), a triangle's area (3D meshes), from
// the node coordinates (one column per node). Used to share boundary loads and contact
// tributary measures among a facet's nodes.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>

namespace stc {

inline double facetMeasure(const Eigen::MatrixXd& x, const std::array<int, 2>& edge) {
  return (x.col(edge[0]) - x.col(edge[1])).norm();
}

/// Half the norm of (x1 − x0) × (x2 − x0).
inline double facetMeasure(const Eigen::MatrixXd& x, const std::array<int, 3>& t) {
  const Eigen::Vector3d a = x.col(t[1]) - x.col(t[0]), b = x.col(t[2]) - x.col(t[0]);
  return 0.5 * a.cross(b).norm();
}

}  // namespace stc
