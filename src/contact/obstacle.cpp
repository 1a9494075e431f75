#include "stcontact/contact/obstacle.hpp"

#include <algorithm>
#include <limits>
#include <utility>

#include "stcontact/core/input_error.hpp"
#include "stcontact/core/overloaded.hpp"
#include "stcontact/mesh/gmsh_reader.hpp"

namespace stc {
namespace {

struct ClosestPoint {
  Eigen::Vector2d normal;  // unit, into the body
  double gap = 0.0;        // signed distance, negative inside the obstacle
};

Eigen::Vector2d segmentNormal(const Eigen::Matrix2Xd& p, Eigen::Index s) {
  const Eigen::Vector2d t = (p.col(s + 1) - p.col(s)).normalized();
  return {-t.y(), t.x()};
}

// The mean normal of the segments at vertex v (one at an end).
Eigen::Vector2d vertexNormal(const Eigen::Matrix2Xd& p, Eigen::Index v) {
  Eigen::Vector2d n = Eigen::Vector2d::Zero();
  if (v > 0) n += segmentNormal(p, v - 1);
  if (v + 1 < p.cols()) n += segmentNormal(p, v);
  return n.normalized();
}

ClosestPoint closestPoint(const PolylineObstacle& line, const Eigen::Vector2d& x) {
  const Eigen::Matrix2Xd& p = line.points;
  double best = std::numeric_limits<double>::infinity();
  ClosestPoint out;
  for (Eigen::Index s = 0; s + 1 < p.cols(); ++s) {
    const Eigen::Vector2d a = p.col(s), t = p.col(s + 1) - a;
    const double u = std::clamp((x - a).dot(t) / t.squaredNorm(), 0.0, 1.0);
    const Eigen::Vector2d r = x - (a + u * t);
    const double distance = r.norm();
    if (!(distance < best)) continue;
    best = distance;
    if (u > 0.0 && u < 1.0) {  // inside the segment
      out.normal = segmentNormal(p, s);
      out.gap = r.dot(out.normal);
      continue;
    }
    const Eigen::Vector2d mean = vertexNormal(p, u == 0.0 ? s : s + 1);
    const double side = r.dot(mean) >= 0.0 ? 1.0 : -1.0;
    out.normal = distance > 0.0 ? Eigen::Vector2d(side * r / distance) : mean;
    out.gap = side * distance;
  }
  return out;
}

}  // namespace

Obstacle makeObstacle(const ObstacleSpec& spec) {
  switch (spec.type) {
    case ObstacleType::Plane:
      return PlaneObstacle{spec.point, spec.normal.normalized()};
    case ObstacleType::Sphere:
    case ObstacleType::Cylinder:
      return BallObstacle{spec.centre, spec.radius, spec.inside};
    case ObstacleType::Polyline:
      return PolylineObstacle{spec.points};
    case ObstacleType::Surface: {
      SurfaceTriangles surface = readGmshSurface(spec.file);
      return makeSurfaceObstacle(std::move(surface.nodes), std::move(surface.triangles), spec.inside);
    }
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
                               },
                               [&](const PolylineObstacle& line) -> Eigen::VectorXd {
                                 return closestPoint(line, x).normal;
                               },
                               [&](const SurfaceObstacle& surface) -> Eigen::VectorXd {
                                 return closestSurfacePoint(surface, x).normal;
                               }},
                    obstacle);
}

double obstacleGap(const Obstacle& obstacle, const Eigen::VectorXd& x) {
  return std::visit(Overloaded{[&](const PlaneObstacle& plane) { return (x - plane.point).dot(plane.normal); },
                               [&](const BallObstacle& ball) {
                                 const double distance = (x - ball.centre).norm();
                                 return ball.inside ? ball.radius - distance : distance - ball.radius;
                               },
                               [&](const PolylineObstacle& line) { return closestPoint(line, x).gap; },
                               [&](const SurfaceObstacle& surface) { return closestSurfacePoint(surface, x).gap; }},
                    obstacle);
}

}  // namespace stc
