#pragma once
// Rigid obstacles. Only a plane for now; the variant keeps room for a circle (or any shape that
// can give a signed distance and an outward normal at a point).
#include <Eigen/Core>
#include <variant>

#include "src/scene/scene.hpp"

namespace stc {

/// The half-plane below the line through `point` with unit `normal` pointing into the body.
struct PlaneObstacle {
  Eigen::Vector2d point;
  Eigen::Vector2d normal;
};

using Obstacle = std::variant<PlaneObstacle>;

Obstacle makeObstacle(const ObstacleSpec& spec);

/// Unit normal n at x, pointing from the obstacle into the body (docs/method.md §1).
Eigen::Vector2d obstacleNormal(const Obstacle& obstacle, const Eigen::Vector2d& x);

/// Signed initial gap g0 = (x − x_obs)·n (negative: x is inside the obstacle).
double obstacleGap(const Obstacle& obstacle, const Eigen::Vector2d& x);

}  // namespace stc
