#include "stcontact/contact/obstacle.hpp"

#include "stcontact/core/input_error.hpp"
#include "stcontact/core/overloaded.hpp"

namespace stc {

Obstacle makeObstacle(const ObstacleSpec& spec) {
  switch (spec.type) {
    case ObstacleType::Plane:
      return PlaneObstacle{spec.point, spec.normal.normalized()};
    case ObstacleType::Sphere:
    case ObstacleType::Cylinder:
      return BallObstacle{spec.centre, spec.radius, spec.inside};
  }
  return PlaneObstacle{spec.point, spec.normal.normalized()};
}

Eigen::VectorXd obstacleNormal(const Obstacle& obstacle, const Eigen::VectorXd& x) {
  return std::visit(Overloaded{[](const PlaneObstacle& plane) -> Eigen::VectorXd { return plane.normal; },
                               [&](const BallObstacle& ball) -> Eigen::VectorXd {
                                 const Eigen::VectorXd r = x - ball.centre;
                                 const double distance = r.norm();
                                 if (!(distance > 0.0))
                                   throw InputError("a contact node lies at the obstacle's centre, where its normal "
                                                    "is undefined (check obstacle.centre)");
                                 return (ball.inside ? -1.0 : 1.0) * r / distance;
                               }},
                    obstacle);
}

double obstacleGap(const Obstacle& obstacle, const Eigen::VectorXd& x) {
  return std::visit(Overloaded{[&](const PlaneObstacle& plane) { return (x - plane.point).dot(plane.normal); },
                               [&](const BallObstacle& ball) {
                                 const double distance = (x - ball.centre).norm();
                                 return ball.inside ? ball.radius - distance : distance - ball.radius;
                               }},
                    obstacle);
}

}  // namespace stc
