#pragma once
// The structured grid of the reference box Q = [−1, 1]² × [−1, 0] that both half-ball meshes start
// from (src/mesh/half_ball.hpp), its Kuhn split into tetrahedra and the map of Q onto the half ball.
#include <Eigen/Core>
#include <algorithm>
#include <cstdlib>

namespace stc::detail {

/// Node (i, j, k), 0 <= i, j <= 2d, 0 <= k <= d, at x = (i − d)/d, y = (j − d)/d, z = k/d − 1.
class BoxGrid {
 public:
  explicit BoxGrid(int divisions) : d_(divisions), side_(2 * divisions + 1) {}

  int id(int i, int j, int k) const { return i + side_ * (j + side_ * k); }
  int column(int id) const { return id % side_; }         // i
  int row(int id) const { return (id / side_) % side_; }  // j
  int layer(int id) const { return id / (side_ * side_); }  // k
  int numNodes() const { return side_ * side_ * (d_ + 1); }
  int divisions() const { return d_; }

  Eigen::Vector3d reference(int id) const {
    return {double(column(id) - d_) / d_, double(row(id) - d_) / d_, double(layer(id)) / d_ - 1.0};
  }

  /// ‖x − P‖_∞ with P = (0, 0, −1) the bottom pole, from the integer indices so that the faces stay exact.
  double poleDistance(int id) const {
    return double(std::max({std::abs(column(id) - d_), std::abs(row(id) - d_), layer(id)})) / d_;
  }

 private:
  int d_, side_;
};

/// The 2d × 2d × d cubes, each split into 6 tetrahedra around its diagonal that points away from
/// the centre of the top face (neighbouring cubes share their face diagonals), positive volume in
/// the reference box. The cubes of the half-box of `hole` cells around P (‖x − P‖_∞ <= hole / d)
/// are left out (0: none).
Eigen::Matrix4Xi boxTetrahedra(const BoxGrid& grid, int hole = 0);

/// Q onto the half unit ball: x ↦ x ‖x‖_∞ / ‖x‖₂ (the five faces other than z = 0 go onto the
/// hemisphere, the face z = 0 onto the unit disc).
Eigen::Vector3d boxToBall(const Eigen::Vector3d& x);

/// ((b − a) × (c − a)) · (e − a).
double sixVolume(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                 const Eigen::Vector3d& e);

}  // namespace stc::detail
