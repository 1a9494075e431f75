#include "stcontact/contact/contact_interface.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

#include "stcontact/contact/node_pairing.hpp"
#include "stcontact/core/input_error.hpp"
#include "stcontact/mesh/facet_measure.hpp"

namespace stc {
namespace {

// Exactly ±1 or 0 up to round-off of a unit normal's components.
constexpr double kAxisTolerance = 1e-12;

// What the interface needs of a group node: its normal and initial gap, and its master node when
// it faces another body (−1: a rigid obstacle) with the master nodes it is compared with and their
// weights (contact/node_pairing.hpp, NodePair).
struct NodeGeometry {
  Eigen::VectorXd normal;
  double gap = 0.0;
  int master = -1;
  std::vector<int> facet;
  std::vector<double> weights;
};

// A master node may have components prescribed only held at 0 (its B entries are then left out):
// a master moved by a history would move the gap by a known amount the interface cannot carry.
void requireMasterHeldOrFree(const Eigen::MatrixXd& positions, int master, const DofStatus& dofs) {
  const int dim = static_cast<int>(positions.rows());
  for (int a = 0; a < dim; ++a)
    if (dofs.free_index[dim * master + a] < 0 && !dofs.zero[dim * master + a])
      throw InputError("contact.master: " + describeNode(positions, master) + " has a prescribed displacement component " +
                       "xyz"[a] + " that is not held at 0; a master node facing a free slave node may only be free or "
                       "held at 0");
}

// A group node is left out of the interface when its motion along its normal n is known: every dof
// prescribed, or a prescribed axis along n (|n · e_a| = 1).
bool leftOut(int node, const Eigen::VectorXd& n, const DofStatus& dofs) {
  const auto dim = static_cast<int>(n.size());
  const auto prescribed = [&](int a) { return dofs.free_index[static_cast<size_t>(dim * node + a)] < 0; };
  bool all = true, along_normal = false;
  for (int a = 0; a < dim; ++a) {
    all = all && prescribed(a);
    along_normal = along_normal || (prescribed(a) && std::abs(n[a]) >= 1.0 - kAxisTolerance);
  }
  return all || along_normal;
}

// The group's contact nodes: the rule of buildContactInterface (header), with each node's geometry.
template <class GeometryOf>
std::vector<int> contactNodes(const Eigen::MatrixXd& positions, const std::vector<int>& group_nodes,
                              const std::string& boundary, const GeometryOf& geometry_of, const DofStatus& dofs) {
  const int dim = static_cast<int>(positions.rows());
  std::vector<int> nodes;
  for (int node : group_nodes) {
    const NodeGeometry g = geometry_of(node);
    const Eigen::VectorXd& n = g.normal;
    const auto prescribed = [&](int a) { return dofs.free_index[dim * node + a] < 0; };
    if (leftOut(node, n, dofs)) continue;  // its motion normal to the obstacle is known
    for (int a = 0; a < dim; ++a)
      if (prescribed(a) && (std::abs(n[a]) > kAxisTolerance || !dofs.zero[dim * node + a]))
        throw InputError("contact boundary '" + boundary + "': " + describeNode(positions, node) +
                         " has a prescribed displacement component " + "xyz"[a] +
                         "; a contact node may only have components prescribed along its normal, or held at 0 "
                         "along an axis orthogonal to it");
    for (int master : g.facet) requireMasterHeldOrFree(positions, master, dofs);
    nodes.push_back(node);
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

// τ lies along a prescribed axis of `node` (and of each of its master nodes, when it has some).
bool heldTangent(const Eigen::VectorXd& tangent, const std::vector<int>& free_index, int node, const std::vector<int>& masters) {
  const Eigen::Index dim = tangent.size();
  const auto free = [&](int n, Eigen::Index a) { return free_index[static_cast<size_t>(dim * n + a)] >= 0; };
  for (Eigen::Index a = 0; a < dim; ++a) {
    if (std::abs(tangent[a]) <= kAxisTolerance) continue;
    if (free(node, a) || std::any_of(masters.begin(), masters.end(), [&](int m) { return free(m, a); })) return false;
  }
  return true;
}

// Column i of the master matrices (header: ContactInterface::master_facets) from the pairs' facets.
void storeMasters(ContactInterface& c, const std::vector<NodeGeometry>& pairs) {
  size_t rows = 0;
  for (const NodeGeometry& g : pairs) rows = std::max(rows, g.facet.size());
  c.master_facets = Eigen::MatrixXi::Constant(static_cast<Eigen::Index>(rows), c.size(), -1);
  c.master_weights = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(rows), c.size());
  for (int i = 0; i < c.size(); ++i)
    for (size_t j = 0; j < pairs[static_cast<size_t>(i)].facet.size(); ++j) {
      c.master_facets(static_cast<Eigen::Index>(j), i) = pairs[static_cast<size_t>(i)].facet[j];
      c.master_weights(static_cast<Eigen::Index>(j), i) = pairs[static_cast<size_t>(i)].weights[j];
    }
}

void checkGap(const ContactInterface& c, const Eigen::MatrixXd& positions, int i) {
  if (c.initial_gap[i] >= 0.0) return;
  std::ostringstream msg;
  msg << "contact " << describeNode(positions, c.nodes[i]) << " starts inside the obstacle (initial gap "
      << c.initial_gap[i] << " < 0; check the [obstacle] table)";
  throw InputError(msg.str());
}

// Rows of node i in B: +n, +τ on the node's free dofs, −n, −τ on its master's (u_s − u_m).
void addRows(const ContactInterface& c, int i, int node, double sign, const std::vector<int>& free_index,
             std::vector<Eigen::Triplet<double>>& triplets) {
  const int dim = c.dimension;
  for (int d = 0; d < dim; ++d) {
    const int dof = free_index[dim * node + d];
    if (dof < 0) continue;  // held at 0 (contactNodes)
    triplets.emplace_back(c.normalRow(i), dof, sign * c.normals(d, i));
    for (int a = 0; a < dim - 1; ++a)
      triplets.emplace_back(c.normalRow(i) + 1 + a, dof, sign * c.tangents(d, (dim - 1) * i + a));
  }
}

// The interface on a group whose boundary `facets` are edges (2D) or triangles (3D); each facet
// gives an equal share of its measure to each of its nodes (1/2 of an edge, 1/3 of a triangle).
template <class Facet, class GeometryOf>
ContactInterface build(const Eigen::MatrixXd& positions, const std::vector<int>& group_nodes,
                       const std::vector<Facet>& facets, const std::string& boundary, const GeometryOf& geometry_of,
                       const DofStatus& dofs, double friction) {
  const std::vector<int>& free_index = dofs.free_index;
  const int dim = static_cast<int>(positions.rows());
  ContactInterface c;
  c.dimension = dim;
  c.nodes = contactNodes(positions, group_nodes, boundary, geometry_of, dofs);
  c.friction = friction;
  const int nc = c.size();
  c.normals.resize(dim, nc);
  c.tangents.resize(dim, (dim - 1) * nc);
  c.initial_gap.resize(nc);
  c.tributary = Eigen::VectorXd::Zero(nc);
  std::vector<int> local(positions.cols(), -1);
  for (int i = 0; i < nc; ++i) local[c.nodes[i]] = i;
  const double share = 1.0 / static_cast<double>(std::tuple_size_v<Facet>);
  c.facet_size = Eigen::VectorXd::Zero(nc);
  Eigen::VectorXd facets_at = Eigen::VectorXd::Zero(nc);
  for (const auto& facet : facets) {
    const double measure = facetMeasure(positions, facet);
    const double size = dim == 3 ? std::sqrt(measure) : measure;
    for (int node : facet)
      if (local[node] >= 0) {
        c.tributary[local[node]] += share * measure;
        c.facet_size[local[node]] += size;
        facets_at[local[node]] += 1.0;
      }
  }
  c.facet_size = c.facet_size.cwiseQuotient(facets_at.cwiseMax(1.0));
  std::vector<Eigen::Triplet<double>> triplets;
  std::vector<NodeGeometry> pairs;
  for (int i = 0; i < nc; ++i) {
    const NodeGeometry g = geometry_of(c.nodes[i]);
    c.normals.col(i) = g.normal;
    c.tangents.middleCols(static_cast<Eigen::Index>(dim - 1) * i, dim - 1) = tangentFrame(c.normals.col(i));
    c.initial_gap[i] = g.gap;
    checkGap(c, positions, i);
    addRows(c, i, c.nodes[i], 1.0, free_index, triplets);
    if (g.master >= 0) {
      c.master_nodes.push_back(g.master);
      for (size_t j = 0; j < g.facet.size(); ++j) addRows(c, i, g.facet[j], -g.weights[j], free_index, triplets);
      pairs.push_back(g);
    }
    for (int a = 0; a < dim - 1; ++a)  // a tangent along a held axis: no free dof moves the node that way
      if (heldTangent(c.tangents.col((dim - 1) * i + a), free_index, c.nodes[i], g.facet))
        c.held_rows.push_back(c.normalRow(i) + 1 + a);
  }
  if (!pairs.empty()) storeMasters(c, pairs);
  const int n_free = static_cast<int>(std::count_if(free_index.begin(), free_index.end(), [](int j) { return j >= 0; }));
  c.B.resize(c.rows(), n_free);
  c.B.setFromTriplets(triplets.begin(), triplets.end());
  return c;
}

// The geometry of a node facing a rigid obstacle.
auto facing(const Eigen::MatrixXd& positions, const Obstacle& obstacle) {
  return [&positions, &obstacle](int node) {
    const Eigen::VectorXd x = positions.col(node);
    return NodeGeometry{obstacleNormal(obstacle, x), obstacleGap(obstacle, x), -1, {}, {}};
  };
}

// The geometry of each slave node paired with a master node or facet (contact/node_pairing.hpp),
// looked up by mesh node id.
// Node to segment pairs only the slave nodes the interface keeps (leftOut along the common normal:
// a rim node held along it may have no master facet on its line).
template <class Mesh>
auto paired(const Mesh& mesh, const std::string& slave, const std::string& master, const Eigen::VectorXd& common_normal,
            bool to_segment, const DofStatus& dofs) {
  std::vector<int> slave_nodes = mesh.group(slave).nodes;
  if (to_segment)
    slave_nodes.erase(std::remove_if(slave_nodes.begin(), slave_nodes.end(), [&](int s) { return leftOut(s, common_normal, dofs); }),
                      slave_nodes.end());
  const std::vector<NodePair> pairs =
      to_segment ? pairNodesToFacets(mesh.nodes, slave_nodes, masterFacets(mesh, master), common_normal)
                 : pairNodes(mesh.nodes, slave_nodes, mesh.group(master).nodes, outwardNodeNormals(mesh, master), common_normal);
  std::vector<NodeGeometry> by_node(static_cast<size_t>(mesh.numNodes()));
  for (int s : mesh.group(slave).nodes) by_node[static_cast<size_t>(s)].normal = common_normal;  // left out: no master
  for (size_t i = 0; i < pairs.size(); ++i)
    by_node[static_cast<size_t>(slave_nodes[i])] = {pairs[i].normal, pairs[i].gap, pairs[i].master, pairs[i].facet, pairs[i].weights};
  return [by_node = std::move(by_node)](int node) { return by_node[static_cast<size_t>(node)]; };
}

}  // namespace

ContactInterface buildContactInterface(const TriMesh& mesh, const std::string& boundary, const Obstacle& obstacle,
                                       const DofStatus& dofs, double friction) {
  const BoundaryGroup& group = mesh.group(boundary);
  return build(mesh.nodes, group.nodes, group.edges, boundary, facing(mesh.nodes, obstacle), dofs, friction);
}

ContactInterface buildContactInterface(const TetMesh& mesh, const std::string& boundary, const Obstacle& obstacle,
                                       const DofStatus& dofs, double friction) {
  const SurfaceGroup& group = mesh.group(boundary);
  return build(mesh.nodes, group.nodes, group.triangles, boundary, facing(mesh.nodes, obstacle), dofs, friction);
}

ContactInterface buildContactPair(const TriMesh& mesh, const std::string& slave, const std::string& master,
                                  const Eigen::VectorXd& common_normal, bool to_segment, const DofStatus& dofs,
                                  double friction) {
  const BoundaryGroup& group = mesh.group(slave);
  return build(mesh.nodes, group.nodes, group.edges, slave, paired(mesh, slave, master, common_normal, to_segment, dofs), dofs,
               friction);
}

ContactInterface buildContactPair(const TetMesh& mesh, const std::string& slave, const std::string& master,
                                  const Eigen::VectorXd& common_normal, bool to_segment, const DofStatus& dofs,
                                  double friction) {
  const SurfaceGroup& group = mesh.group(slave);
  return build(mesh.nodes, group.nodes, group.triangles, slave, paired(mesh, slave, master, common_normal, to_segment, dofs),
               dofs, friction);
}

ContactInterface restrictToNodes(const ContactInterface& contact, const std::vector<int>& nodes) {
  const int d = contact.dimension, count = static_cast<int>(nodes.size());
  const bool has_directions = contact.search_direction.size() == contact.rows();
  ContactInterface sub;
  sub.dimension = d;
  sub.friction = contact.friction;
  sub.search_scale_per_length = contact.search_scale_per_length;
  sub.normals.resize(contact.normals.rows(), count);
  sub.tangents.resize(contact.tangents.rows(), (d - 1) * count);
  sub.initial_gap.resize(count);
  sub.tributary.resize(count);
  sub.facet_size.resize(count);
  sub.search_direction.resize(has_directions ? d * count : 0);
  if (contact.isPair()) {
    sub.master_facets.resize(contact.master_facets.rows(), count);
    sub.master_weights.resize(contact.master_weights.rows(), count);
  }
  std::vector<int> new_row(static_cast<size_t>(contact.rows()), -1);
  std::vector<Eigen::Triplet<double>> select;  // (new row, old row)
  for (int j = 0; j < count; ++j) {
    const int i = nodes[static_cast<size_t>(j)];
    if (i < 0 || i >= contact.size())
      throw std::out_of_range("restrictToNodes: node index " + std::to_string(i));
    sub.nodes.push_back(contact.nodes[static_cast<size_t>(i)]);
    if (contact.isPair()) {
      sub.master_nodes.push_back(contact.master_nodes[static_cast<size_t>(i)]);
      sub.master_facets.col(j) = contact.master_facets.col(i);
      sub.master_weights.col(j) = contact.master_weights.col(i);
    }
    sub.normals.col(j) = contact.normals.col(i);
    sub.tangents.middleCols((d - 1) * j, d - 1) = contact.tangents.middleCols((d - 1) * i, d - 1);
    sub.initial_gap[j] = contact.initial_gap[i];
    sub.tributary[j] = contact.tributary[i];
    sub.facet_size[j] = contact.facet_size[i];
    if (has_directions) sub.search_direction.segment(d * j, d) = contact.search_direction.segment(d * i, d);
    for (int a = 0; a < d; ++a) {
      new_row[static_cast<size_t>(d * i + a)] = d * j + a;
      select.emplace_back(d * j + a, d * i + a, 1.0);
    }
  }
  Eigen::SparseMatrix<double> selection(d * count, contact.rows());
  selection.setFromTriplets(select.begin(), select.end());
  sub.B = selection * contact.B;
  for (int row : contact.held_rows)
    if (new_row[static_cast<size_t>(row)] >= 0) sub.held_rows.push_back(new_row[static_cast<size_t>(row)]);
  std::sort(sub.held_rows.begin(), sub.held_rows.end());
  return sub;
}

std::vector<int> rowsOfNodes(int d, const std::vector<int>& nodes) {
  std::vector<int> rows;
  rows.reserve(nodes.size() * static_cast<size_t>(d));
  for (int i : nodes)
    for (int a = 0; a < d; ++a) rows.push_back(d * i + a);
  return rows;
}

std::vector<int> dofsReadBy(const Eigen::SparseMatrix<double>& B) {
  std::vector<char> read(static_cast<size_t>(B.cols()), 0);
  for (Eigen::Index k = 0; k < B.outerSize(); ++k)
    for (Eigen::SparseMatrix<double>::InnerIterator it(B, k); it; ++it)
      if (it.value() != 0.0) read[static_cast<size_t>(it.col())] = 1;
  std::vector<int> dofs;
  for (Eigen::Index j = 0; j < B.cols(); ++j)
    if (read[static_cast<size_t>(j)]) dofs.push_back(static_cast<int>(j));
  return dofs;
}

std::vector<int> otherNodes(int n, const std::vector<int>& nodes) {
  std::vector<char> in(static_cast<size_t>(n), 0);
  for (int i : nodes) in[static_cast<size_t>(i)] = 1;
  std::vector<int> others;
  for (int i = 0; i < n; ++i)
    if (!in[static_cast<size_t>(i)]) others.push_back(i);
  return others;
}

GlobalVector inGlobalFrame(const ContactInterface& contact, int i, const Eigen::Ref<const Eigen::VectorXd>& local) {
  const int d = contact.dimension;
  return local[0] * contact.normals.col(i) +
         contact.tangents.middleCols(static_cast<Eigen::Index>(d - 1) * i, d - 1) * local.tail(d - 1);
}

void setSearchDirection(ContactInterface& contact, double kappa, double young, double length_scale,
                        SearchLaw law) {
  contact.search_scale_per_length = kappa * young / length_scale;
  contact.search_direction.resize(contact.rows());
  Eigen::VectorXd k = contact.search_scale_per_length * contact.tributary;
  if (law == SearchLaw::Local) {  // k_i h̄ / h_i, h̄ = Σ ℓ_i / Σ (ℓ_i / h_i) (src/options/search_direction_options.hpp)
    Eigen::VectorXd per_size = Eigen::VectorXd::Zero(contact.size());  // ℓ_i / h_i (0 off every facet)
    for (int i = 0; i < contact.size(); ++i)
      if (contact.facet_size[i] > 0.0) per_size[i] = contact.tributary[i] / contact.facet_size[i];
    if (per_size.sum() > 0.0) k = contact.search_scale_per_length * per_size * (contact.tributary.sum() / per_size.sum());
  }
  for (int i = 0; i < contact.size(); ++i)
    contact.search_direction.segment(contact.normalRow(i), contact.dimension).setConstant(k[i]);
}

}  // namespace stc
