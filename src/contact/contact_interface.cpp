#include "src/contact/contact_interface.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "src/core/input_error.hpp"
#include "src/mesh/facet_measure.hpp"

namespace stc {
namespace {

std::string describeNode(const Eigen::MatrixXd& positions, int node) {
  std::ostringstream out;
  out << "node " << node << " at (";
  for (Eigen::Index d = 0; d < positions.rows(); ++d) out << (d > 0 ? ", " : "") << positions(d, node);
  out << ")";
  return out.str();
}

// Keeps the group's nodes that are free in every direction; rejects partly prescribed ones.
std::vector<int> contactNodes(const Eigen::MatrixXd& positions, const std::vector<int>& group_nodes,
                              const std::string& boundary, const std::vector<int>& free_index) {
  const int dim = static_cast<int>(positions.rows());
  std::vector<int> nodes;
  for (int node : group_nodes) {
    int free = 0;
    for (int d = 0; d < dim; ++d) free += free_index[dim * node + d] >= 0 ? 1 : 0;
    if (free == dim) nodes.push_back(node);
    else if (free > 0)
      throw InputError("contact boundary '" + boundary + "': " + describeNode(positions, node) +
                       " has a prescribed displacement component; a contact node must be free or fully prescribed");
  }
  if (nodes.empty()) throw InputError("contact boundary '" + boundary + "' has no free node");
  return nodes;
}

// Tangential directions of the frame (see the header).
Eigen::MatrixXd tangentFrame(const Eigen::VectorXd& n) {
  if (n.size() == 2) return Eigen::Vector2d(n.y(), -n.x());
  const Eigen::Vector3d normal = n;
  Eigen::Index axis = 0;
  normal.cwiseAbs().minCoeff(&axis);
  const Eigen::Vector3d e = Eigen::Vector3d::Unit(axis);
  Eigen::Matrix<double, 3, 2> t;
  t.col(0) = (e - e.dot(normal) * normal).normalized();
  t.col(1) = normal.cross(Eigen::Vector3d(t.col(0)));
  return t;
}

void checkGap(const ContactInterface& c, const Eigen::MatrixXd& positions, int i) {
  if (c.initial_gap[i] >= 0.0) return;
  std::ostringstream msg;
  msg << "contact " << describeNode(positions, c.nodes[i]) << " starts inside the obstacle (initial gap "
      << c.initial_gap[i] << " < 0; check obstacle.point and obstacle.normal)";
  throw InputError(msg.str());
}

// The interface on a group whose boundary `facets` are edges (2D) or triangles (3D); each facet
// gives an equal share of its measure to each of its nodes (1/2 of an edge, 1/3 of a triangle).
template <class Facet>
ContactInterface build(const Eigen::MatrixXd& positions, const std::vector<int>& group_nodes,
                       const std::vector<Facet>& facets, const std::string& boundary, const Obstacle& obstacle,
                       const std::vector<int>& free_index, double friction) {
  const int dim = static_cast<int>(positions.rows());
  ContactInterface c;
  c.dimension = dim;
  c.nodes = contactNodes(positions, group_nodes, boundary, free_index);
  c.friction = friction;
  const int nc = c.size();
  c.normals.resize(dim, nc);
  c.tangents.resize(dim, (dim - 1) * nc);
  c.initial_gap.resize(nc);
  c.tributary = Eigen::VectorXd::Zero(nc);
  std::vector<int> local(positions.cols(), -1);
  for (int i = 0; i < nc; ++i) local[c.nodes[i]] = i;
  const double share = 1.0 / static_cast<double>(std::tuple_size_v<Facet>);
  for (const auto& facet : facets) {
    const double measure = facetMeasure(positions, facet);
    for (int node : facet)
      if (local[node] >= 0) c.tributary[local[node]] += share * measure;
  }
  std::vector<Eigen::Triplet<double>> triplets;
  for (int i = 0; i < nc; ++i) {
    const Eigen::VectorXd x = positions.col(c.nodes[i]);
    c.normals.col(i) = obstacleNormal(obstacle, x);
    c.tangents.middleCols(static_cast<Eigen::Index>(dim - 1) * i, dim - 1) = tangentFrame(c.normals.col(i));
    c.initial_gap[i] = obstacleGap(obstacle, x);
    checkGap(c, positions, i);
    for (int d = 0; d < dim; ++d) {
      const int dof = free_index[dim * c.nodes[i] + d];
      triplets.emplace_back(c.normalRow(i), dof, c.normals(d, i));
      for (int a = 0; a < dim - 1; ++a) triplets.emplace_back(c.normalRow(i) + 1 + a, dof, c.tangents(d, (dim - 1) * i + a));
    }
  }
  const int n_free = static_cast<int>(std::count_if(free_index.begin(), free_index.end(), [](int j) { return j >= 0; }));
  c.B.resize(c.rows(), n_free);
  c.B.setFromTriplets(triplets.begin(), triplets.end());
  return c;
}

}  // namespace

ContactInterface buildContactInterface(const Mesh& mesh, const std::string& boundary, const Obstacle& obstacle,
                                       const std::vector<int>& free_index, double friction) {
  const BoundaryGroup& group = mesh.group(boundary);
  return build(mesh.nodes, group.nodes, group.edges, boundary, obstacle, free_index, friction);
}

ContactInterface buildContactInterface(const TetMesh& mesh, const std::string& boundary, const Obstacle& obstacle,
                                       const std::vector<int>& free_index, double friction) {
  const SurfaceGroup& group = mesh.group(boundary);
  return build(mesh.nodes, group.nodes, group.triangles, boundary, obstacle, free_index, friction);
}

void setSearchDirection(ContactInterface& contact, double kappa, double young, double length_scale) {
  contact.search_scale_per_length = kappa * young / length_scale;
  contact.search_direction.resize(contact.rows());
  for (int i = 0; i < contact.size(); ++i)
    contact.search_direction.segment(contact.normalRow(i), contact.dimension)
        .setConstant(contact.search_scale_per_length * contact.tributary[i]);
}

}  // namespace stc
