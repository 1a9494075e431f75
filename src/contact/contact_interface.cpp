#include "src/contact/contact_interface.hpp"

#include <algorithm>
#include <sstream>

#include "src/core/input_error.hpp"

namespace stc {
namespace {

std::string describeNode(const Mesh& mesh, int node) {
  std::ostringstream out;
  out << "node " << node << " at (" << mesh.nodes(0, node) << ", " << mesh.nodes(1, node) << ")";
  return out.str();
}

// Keeps the group's nodes that are free in both directions; rejects half-prescribed ones.
std::vector<int> contactNodes(const Mesh& mesh, const std::string& boundary, const std::vector<int>& free_index) {
  std::vector<int> nodes;
  for (int node : mesh.group(boundary).nodes) {
    const bool free_x = free_index[2 * node] >= 0, free_y = free_index[2 * node + 1] >= 0;
    if (free_x && free_y) nodes.push_back(node);
    else if (free_x || free_y)
      throw InputError("contact boundary '" + boundary + "': " + describeNode(mesh, node) +
                       " has one prescribed displacement component; a contact node must be free or fully prescribed");
  }
  if (nodes.empty()) throw InputError("contact boundary '" + boundary + "' has no free node");
  return nodes;
}

}  // namespace

ContactInterface buildContactInterface(const Mesh& mesh, const std::string& boundary, const Obstacle& obstacle,
                                       const std::vector<int>& free_index, double friction) {
  ContactInterface c;
  c.nodes = contactNodes(mesh, boundary, free_index);
  c.friction = friction;
  const int nc = c.size();
  c.normals.resize(2, nc);
  c.tangents.resize(2, nc);
  c.initial_gap.resize(nc);
  c.tributary = Eigen::VectorXd::Zero(nc);
  std::vector<int> local(mesh.numNodes(), -1);
  for (int i = 0; i < nc; ++i) local[c.nodes[i]] = i;
  for (const auto& edge : mesh.group(boundary).edges) {
    const double length = (mesh.nodes.col(edge[0]) - mesh.nodes.col(edge[1])).norm();
    for (int node : edge)
      if (local[node] >= 0) c.tributary[local[node]] += 0.5 * length;
  }
  std::vector<Eigen::Triplet<double>> triplets;
  for (int i = 0; i < nc; ++i) {
    const Eigen::Vector2d x = mesh.nodes.col(c.nodes[i]);
    const Eigen::Vector2d n = obstacleNormal(obstacle, x);
    c.normals.col(i) = n;
    c.tangents.col(i) = Eigen::Vector2d(n.y(), -n.x());
    c.initial_gap[i] = obstacleGap(obstacle, x);
    if (c.initial_gap[i] < 0.0) {
      std::ostringstream msg;
      msg << "contact " << describeNode(mesh, c.nodes[i]) << " starts inside the obstacle (initial gap "
          << c.initial_gap[i] << " < 0; check obstacle.point and obstacle.normal)";
      throw InputError(msg.str());
    }
    for (int d = 0; d < 2; ++d) {
      const int dof = free_index[2 * c.nodes[i] + d];
      triplets.emplace_back(2 * i, dof, n[d]);
      triplets.emplace_back(2 * i + 1, dof, c.tangents(d, i));
    }
  }
  const int n_free = static_cast<int>(std::count_if(free_index.begin(), free_index.end(), [](int j) { return j >= 0; }));
  c.B.resize(2 * nc, n_free);
  c.B.setFromTriplets(triplets.begin(), triplets.end());
  return c;
}

void setSearchDirection(ContactInterface& contact, double kappa, double young, double length_scale) {
  contact.search_scale_per_length = kappa * young / length_scale;
  contact.search_direction.resize(2 * contact.size());
  for (int i = 0; i < contact.size(); ++i)
    contact.search_direction.segment<2>(2 * i).setConstant(contact.search_scale_per_length * contact.tributary[i]);
}

}  // namespace stc
