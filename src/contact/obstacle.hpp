#pragma once
// Rigid obstacles: a plane, a ball (a sphere in 3D, a cylinder's circular section in 2D) that the
// body lies outside of, or inside of (a seat), a polyline (2D) the body lies to the left of, or a
// triangulated surface (3D, surface_obstacle.hpp). Each gives the signed distance of a point and the unit
// normal pointing from the obstacle into the body; the contact interface takes both at the nodes'
// initial positions (small sliding, docs/method.md §1). Points have the scene's dimension.
#include <Eigen/Core>
#include <variant>

#include "stcontact/contact/surface_obstacle.hpp"
#include "stcontact/scene/model_spec.hpp"

namespace stc {

/// The half-space below the plane (a line in 2D) through `point` with unit `normal` pointing into
/// the body.
struct PlaneObstacle {
  Eigen::VectorXd point;
  Eigen::VectorXd normal;
};

/// The ball |x − centre| ≤ radius (inside = false), or its complement (inside = true: the body lies
/// in the ball, the obstacle around it). g0 = |x − c| − R, n = (x − c)/|x − c| outside;
/// g0 = R − |x − c|, n = (c − x)/|x − c| inside.
struct BallObstacle {
  Eigen::VectorXd centre;
  double radius = 0.0;
  bool inside = false;
};

/// The polyline through `points` (2 × p, p ≥ 2, consecutive points distinct), the body on its left
/// as one walks along it (the normal of segment t is (−t_y, t_x) / |t|). A point's gap and normal
/// come from its closest point on the polyline: inside a segment, the segment's normal and the
/// signed distance to its line; at a vertex (or beyond an end), the unit vector from the vertex to
/// the point, signed by the side of the vertex's mean normal (the pseudo-normal of a signed
/// distance), or the mean normal itself for a point on the vertex.
struct PolylineObstacle {
  Eigen::Matrix2Xd points;
};

using Obstacle = std::variant<PlaneObstacle, BallObstacle, PolylineObstacle, SurfaceObstacle>;

/// The obstacle of the scene's [obstacle] table; a surface's file is read here (mesh/gmsh_reader.hpp,
/// readGmshSurface: an InputError names the file).
Obstacle makeObstacle(const ObstacleSpec& spec);

/// Unit normal n at x, pointing from the obstacle into the body (docs/method.md §1). A ball's normal
/// at its centre is undefined: InputError.
Eigen::VectorXd obstacleNormal(const Obstacle& obstacle, const Eigen::VectorXd& x);

/// Signed initial gap g0 = (x − x_obs)·n (negative: x is inside the obstacle).
double obstacleGap(const Obstacle& obstacle, const Eigen::VectorXd& x);

}  // namespace stc
