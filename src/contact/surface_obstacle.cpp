#include "stcontact/contact/surface_obstacle.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>

namespace stc {
namespace {

std::pair<int, int> edgeKey(int a, int b) { return {std::min(a, b), std::max(a, b)}; }

// Where the closest point of a triangle lies: inside it, on its edge (a, b), or at its vertex a.
struct TrianglePoint {
  Eigen::Vector3d point;
  int a = -1, b = -1;  // local corners: (−1, −1) inside, (a, b) an edge, (a, −1) a vertex
};

// Ericson §5.1.5: the Voronoi regions of the vertices, then of the edges, else the face.
TrianglePoint closestOnTriangle(const Eigen::Vector3d& x, const Eigen::Vector3d& p0, const Eigen::Vector3d& p1,
                                const Eigen::Vector3d& p2) {
  const Eigen::Vector3d ab = p1 - p0, ac = p2 - p0, ap = x - p0;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0) return {p0, 0, -1};
  const Eigen::Vector3d bp = x - p1;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3) return {p1, 1, -1};
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return {p0 + d1 / (d1 - d3) * ab, 0, 1};
  const Eigen::Vector3d cp = x - p2;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6) return {p2, 2, -1};
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return {p0 + d2 / (d2 - d6) * ac, 0, 2};
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) return {p1 + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (p2 - p1), 1, 2};
  const double denominator = 1.0 / (va + vb + vc);
  return {p0 + ab * (vb * denominator) + ac * (vc * denominator), -1, -1};
}

}  // namespace

SurfaceObstacle makeSurfaceObstacle(Eigen::Matrix3Xd nodes, Eigen::Matrix3Xi triangles, bool inside) {
  SurfaceObstacle s;
  if (inside) triangles.row(1).swap(triangles.row(2));
  s.nodes = std::move(nodes);
  s.triangles = std::move(triangles);
  s.face_normals.resize(3, s.triangles.cols());
  s.vertex_normals = Eigen::Matrix3Xd::Zero(3, s.nodes.cols());
  for (Eigen::Index t = 0; t < s.triangles.cols(); ++t) {
    const Eigen::Vector3d n = (s.nodes.col(s.triangles(1, t)) - s.nodes.col(s.triangles(0, t)))
                                  .cross(s.nodes.col(s.triangles(2, t)) - s.nodes.col(s.triangles(0, t)))
                                  .normalized();
    s.face_normals.col(t) = n;
    for (int c = 0; c < 3; ++c) {
      const int v = s.triangles(c, t), v1 = s.triangles((c + 1) % 3, t), v2 = s.triangles((c + 2) % 3, t);
      const Eigen::Vector3d e1 = (s.nodes.col(v1) - s.nodes.col(v)).normalized(), e2 = (s.nodes.col(v2) - s.nodes.col(v)).normalized();
      s.vertex_normals.col(v) += std::acos(std::clamp(e1.dot(e2), -1.0, 1.0)) * n;  // the angle at v
      auto [edge, fresh] = s.edge_normals.try_emplace(edgeKey(v, v1), Eigen::Vector3d::Zero());
      edge->second += n;
    }
  }
  s.vertex_normals.colwise().normalize();
  for (auto& [edge, n] : s.edge_normals) n.normalize();
  return s;
}

SurfacePoint closestSurfacePoint(const SurfaceObstacle& s, const Eigen::Vector3d& x) {
  double best = std::numeric_limits<double>::infinity();
  SurfacePoint out;
  for (Eigen::Index t = 0; t < s.triangles.cols(); ++t) {
    const TrianglePoint c = closestOnTriangle(x, s.nodes.col(s.triangles(0, t)), s.nodes.col(s.triangles(1, t)),
                                              s.nodes.col(s.triangles(2, t)));
    const Eigen::Vector3d r = x - c.point;
    const double distance = r.norm();
    if (!(distance < best)) continue;
    best = distance;
    if (c.a < 0) {  // inside the triangle
      out.normal = s.face_normals.col(t);
      out.gap = r.dot(out.normal);
      continue;
    }
    const Eigen::Vector3d pseudo = c.b < 0 ? Eigen::Vector3d(s.vertex_normals.col(s.triangles(c.a, t)))
                                           : s.edge_normals.at(edgeKey(s.triangles(c.a, t), s.triangles(c.b, t)));
    const double side = r.dot(pseudo) >= 0.0 ? 1.0 : -1.0;
    out.normal = distance > 0.0 ? Eigen::Vector3d(side * r / distance) : pseudo;
    out.gap = side * distance;
  }
  return out;
}

}  // namespace stc
