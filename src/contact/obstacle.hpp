#pragma once
// Rigid obstacles. Only a plane for now; the variant keeps room for a circle or a sphere (or any
// shape that can give a signed distance and an outward normal at a point). Points and normals have
// the scene's dimension (2 or 3 entries).
#include <Eigen/Core>
#include <variant>

#include "stcontact/scene/scene.hpp"

namespace stc {

/// The half-space below the plane (a line in 2D) through `point` with unit `normal` pointing into
/// the body.
struct PlaneObstacle {
  Eigen::VectorXd point;
  Eigen::VectorXd normal;
};

using Obstacle = std::variant<PlaneObstacle>;

Obstacle makeObstacle(const ObstacleSpec& spec);

/// Unit normal n at x, pointing from the obstacle into the body (docs/method.md §1).
Eigen::VectorXd obstacleNormal(const Obstacle& obstacle, const Eigen::VectorXd& x);

/// Signed initial gap g0 = (x − x_obs)·n (negative: x is inside the obstacle).
double obstacleGap(const Obstacle& obstacle, const Eigen::VectorXd& x);

}  // namespace stc
