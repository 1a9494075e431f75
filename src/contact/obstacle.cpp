#include "stcontact/contact/obstacle.hpp"

namespace stc {

Obstacle makeObstacle(const ObstacleSpec& spec) {
  switch (spec.type) {
    case ObstacleType::Plane:
      break;
  }
  return PlaneObstacle{spec.point, spec.normal.normalized()};
}

Eigen::VectorXd obstacleNormal(const Obstacle& obstacle, const Eigen::VectorXd& /*x*/) {
  return std::visit([](const PlaneObstacle& plane) { return plane.normal; }, obstacle);
}

double obstacleGap(const Obstacle& obstacle, const Eigen::VectorXd& x) {
  return std::visit([&](const PlaneObstacle& plane) { return (x - plane.point).dot(plane.normal); }, obstacle);
}

}  // namespace stc
