#pragma once
// A rigid obstacle given as a triangulated surface in 3D (obstacle.type = "surface", a Gmsh surface
// mesh; docs/scene_format.md): the body lies on the side its triangles' normals
// (x1 − x0) × (x2 − x0) point to ("outside"), or on the other ("inside"). A point's gap and normal
// come from its closest point on the surface (small sliding: at the nodes' initial positions):
//  - inside a triangle: the triangle's unit normal n and the signed distance n · (x − p);
//  - on an edge or at a vertex: the unit vector from p to x, signed by the side of the pseudo-normal
//    there — an edge's is the mean of its triangles' normals, a vertex's their mean weighted by the
//    triangles' angles at it (J. A. Bærentzen, H. Aanæs, "Signed distance computation using the angle
//    weighted pseudonormal", IEEE TVCG 11 (2005) 243–253: the sign is then right for any point) —
//    or the pseudo-normal itself for a point on the surface.
// The closest point on a triangle: C. Ericson, Real-Time Collision Detection (2005), §5.1.5. Every
// triangle is searched (O(triangles) per node, at set-up only).
#include <Eigen/Core>
#include <map>
#include <utility>

namespace stc {

struct SurfaceObstacle {
  Eigen::Matrix3Xd nodes;
  Eigen::Matrix3Xi triangles;       ///< oriented so that their normals point into the body
  Eigen::Matrix3Xd face_normals;    ///< unit, one per triangle
  Eigen::Matrix3Xd vertex_normals;  ///< unit angle-weighted pseudo-normals, one per node
  std::map<std::pair<int, int>, Eigen::Vector3d> edge_normals;  ///< (smaller node, larger node) -> unit
};

/// The obstacle of these triangles, their orientation reversed when `inside`.
SurfaceObstacle makeSurfaceObstacle(Eigen::Matrix3Xd nodes, Eigen::Matrix3Xi triangles, bool inside);

struct SurfacePoint {
  Eigen::Vector3d normal;  ///< unit, from the obstacle into the body
  double gap = 0.0;        ///< signed distance, negative inside the obstacle
};

/// The gap and normal of x (see the top of this header).
SurfacePoint closestSurfacePoint(const SurfaceObstacle& surface, const Eigen::Vector3d& x);

}  // namespace stc
