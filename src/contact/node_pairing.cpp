#include "stcontact/contact/node_pairing.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "stcontact/core/input_error.hpp"

namespace stc {
namespace {

// Coincident nodes: apart by less than this share of the interface's extent.
constexpr double kCoincident = 1e-9;
// A master node right below a slave node along the common normal: off the line by less than this
// share of the interface's extent.
constexpr double kOnTheLine = 1e-6;
// n · n_m below cos 60°: the pair does not face the master boundary. Along a common normal the
// master surface may turn up to 90° away (the far ends of a cylinder's arc, never reached).
constexpr double kFacingCosine = 0.5;
constexpr double kFacingCosineAlongNormal = -1e-9;

// Sums each facet's measure-weighted outward normal `facet_normal(facet)` on its nodes in the group.
template <class Facet, class Normal>
Eigen::MatrixXd accumulate(const std::vector<int>& group_nodes, int num_nodes, int dim,
                           const std::vector<Facet>& facets, Normal&& facet_normal) {
  std::vector<int> local(static_cast<size_t>(num_nodes), -1);
  for (size_t i = 0; i < group_nodes.size(); ++i) local[static_cast<size_t>(group_nodes[i])] = static_cast<int>(i);
  Eigen::MatrixXd normals = Eigen::MatrixXd::Zero(dim, static_cast<Eigen::Index>(group_nodes.size()));
  for (const Facet& facet : facets) {
    bool inside = true;
    for (int node : facet) inside = inside && local[static_cast<size_t>(node)] >= 0;
    if (!inside) continue;
    const Eigen::VectorXd n = facet_normal(facet);
    for (int node : facet) normals.col(local[static_cast<size_t>(node)]) += n;
  }
  for (Eigen::Index i = 0; i < normals.cols(); ++i) {
    const double norm = normals.col(i).norm();
    if (norm > 0.0) normals.col(i) /= norm;
  }
  return normals;
}

}  // namespace

std::string describeNode(const Eigen::MatrixXd& positions, int node) {
  std::ostringstream out;
  out << "node " << node << " at (";
  for (Eigen::Index a = 0; a < positions.rows(); ++a) out << (a > 0 ? ", " : "") << positions(a, node);
  out << ")";
  return out.str();
}

Eigen::MatrixXd outwardNodeNormals(const TriMesh& mesh, const std::string& group) {
  // boundaryEdges runs each edge with the body on its left: (t_y, −t_x) points out, |t| long.
  return accumulate(mesh.group(group).nodes, mesh.numNodes(), 2, boundaryEdges(mesh), [&](const auto& e) {
    const Eigen::Vector2d t = mesh.nodes.col(e[1]) - mesh.nodes.col(e[0]);
    return Eigen::VectorXd(Eigen::Vector2d(t.y(), -t.x()));
  });
}

Eigen::MatrixXd outwardNodeNormals(const TetMesh& mesh, const std::string& group) {
  // boundaryTriangles are counter-clockwise seen from outside: (x1 − x0) × (x2 − x0) points out,
  // twice the area long.
  return accumulate(mesh.group(group).nodes, mesh.numNodes(), 3, boundaryTriangles(mesh), [&](const auto& f) {
    const Eigen::Vector3d a = mesh.nodes.col(f[1]) - mesh.nodes.col(f[0]);
    const Eigen::Vector3d b = mesh.nodes.col(f[2]) - mesh.nodes.col(f[0]);
    return Eigen::VectorXd(a.cross(b));
  });
}

namespace {

// The nearest master node to slave node s (column of xm), by brute force: O(n_master).
NodePair nearestPair(const Eigen::MatrixXd& positions, int s, const Eigen::MatrixXd& xm, const std::vector<int>& master_nodes,
                     const Eigen::MatrixXd& master_normals, double extent, Eigen::Index& j) {
  (xm.colwise() - positions.col(s)).colwise().squaredNorm().minCoeff(&j);
  const int m = master_nodes[static_cast<size_t>(j)];
  const Eigen::VectorXd d = positions.col(s) - positions.col(m);
  const double distance = d.norm();
  if (distance > kCoincident * extent) return {m, d / distance, distance};
  return {m, master_normals.col(j), 0.0};
}

// The master node on the line through slave node s along the common normal n̄, on its master side.
NodePair alongNormal(const Eigen::MatrixXd& positions, int s, const Eigen::MatrixXd& xm, const std::vector<int>& master_nodes,
                     const Eigen::VectorXd& normal, double extent, Eigen::Index& j) {
  const Eigen::MatrixXd d = (-xm).colwise() + positions.col(s);  // x_s − x_m, one column per master node
  const Eigen::RowVectorXd along = normal.transpose() * d;
  const Eigen::RowVectorXd off = (d - normal * along).colwise().norm();
  double best = std::numeric_limits<double>::infinity();
  for (Eigen::Index k = 0; k < d.cols(); ++k)
    if (along[k] >= -kCoincident * extent && off[k] < best) {
      best = off[k];
      j = k;
    }
  if (!(best <= kOnTheLine * extent)) {
    const std::string nearest = std::isfinite(best) ? "the nearest is " + std::to_string(best) + " off it"
                                                    : "no master node lies on the master's side along it";
    throw InputError("slave " + describeNode(positions, s) + " has no master node on its line along contact.normal (" +
                     nearest + "): the bodies overlap, contact.normal points from the slave into the master, or the "
                     "interface meshes do not match (node-to-node contact needs matching meshes)");
  }
  return {master_nodes[static_cast<size_t>(j)], normal, std::max(along[j], 0.0)};
}

}  // namespace

std::vector<NodePair> pairNodes(const Eigen::MatrixXd& positions, const std::vector<int>& slave_nodes,
                                const std::vector<int>& master_nodes, const Eigen::MatrixXd& master_normals,
                                const Eigen::VectorXd& common_normal) {
  if (master_nodes.empty()) throw InputError("the master boundary has no node");
  const Eigen::MatrixXd xm = positions(Eigen::all, master_nodes);
  const double extent = (xm.rowwise().maxCoeff() - xm.rowwise().minCoeff()).norm();
  std::vector<int> paired_with(master_nodes.size(), -1);
  std::vector<NodePair> pairs;
  pairs.reserve(slave_nodes.size());
  for (int s : slave_nodes) {
    Eigen::Index j = 0;
    NodePair pair = common_normal.size() > 0
                        ? alongNormal(positions, s, xm, master_nodes, common_normal, extent, j)
                        : nearestPair(positions, s, xm, master_nodes, master_normals, extent, j);
    const int m = pair.master;
    if (pair.normal.dot(master_normals.col(j)) < (common_normal.size() > 0 ? kFacingCosineAlongNormal : kFacingCosine))
      throw InputError("slave " + describeNode(positions, s) + " does not face the master boundary: its master " +
                       describeNode(positions, m) + " is off the master's outward normal there (by more than 60°, or 90° along contact.normal: the bodies "
                       "overlap, the boundaries do not face each other, or the interface meshes do not match)");
    if (paired_with[static_cast<size_t>(j)] >= 0)
      throw InputError("master " + describeNode(positions, m) + " is paired with two slave nodes (" +
                       std::to_string(paired_with[static_cast<size_t>(j)]) + " and " + std::to_string(s) +
                       "): node-to-node contact needs matching interface meshes (one master node per slave node)");
    paired_with[static_cast<size_t>(j)] = s;
    pairs.push_back(std::move(pair));
  }
  return pairs;
}

}  // namespace stc
