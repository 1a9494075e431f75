#include "stcontact/contact/node_pairing.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
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

// Weights of a node-to-segment pair below this are dropped (the slave right above a master node).
constexpr double kNegligibleWeight = 1e-12;
// A point on a facet's edge or corner: barycentric weights down to this.
constexpr double kOnTheFacet = -1e-9;

// The boundary facets whose nodes all lie in the group (the group's local index of each mesh node).
template <class Facet>
std::vector<Facet> facetsInGroup(const std::vector<int>& local, const std::vector<Facet>& facets) {
  std::vector<Facet> inside;
  for (const Facet& facet : facets)
    if (std::all_of(facet.begin(), facet.end(), [&](int node) { return local[static_cast<size_t>(node)] >= 0; }))
      inside.push_back(facet);
  return inside;
}

std::vector<int> localIndex(const std::vector<int>& group_nodes, int num_nodes) {
  std::vector<int> local(static_cast<size_t>(num_nodes), -1);
  for (size_t i = 0; i < group_nodes.size(); ++i) local[static_cast<size_t>(group_nodes[i])] = static_cast<int>(i);
  return local;
}

// Sums each facet's measure-weighted outward normal `facet_normal(facet)` on its nodes in the group.
template <class Facet, class Normal>
Eigen::MatrixXd accumulate(const std::vector<int>& group_nodes, int num_nodes, int dim,
                           const std::vector<Facet>& facets, Normal&& facet_normal) {
  const std::vector<int> local = localIndex(group_nodes, num_nodes);
  Eigen::MatrixXd normals = Eigen::MatrixXd::Zero(dim, static_cast<Eigen::Index>(group_nodes.size()));
  for (const Facet& facet : facetsInGroup(local, facets)) {
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
  if (distance > kCoincident * extent) return {m, d / distance, distance, {m}, {1.0}};
  return {m, master_normals.col(j), 0.0, {m}, {1.0}};
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
                     "interface meshes do not match (node-to-node contact needs matching meshes; contact.pairing = "
                     "\"segment\" pairs non-matching ones)");
  }
  const int m = master_nodes[static_cast<size_t>(j)];
  return {m, normal, std::max(along[j], 0.0), {m}, {1.0}};
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
                       "): node-to-node contact needs matching interface meshes (one master node per slave node; contact.pairing "
                       "= \"segment\" pairs non-matching ones)");
    paired_with[static_cast<size_t>(j)] = s;
    pairs.push_back(std::move(pair));
  }
  return pairs;
}

std::vector<std::vector<int>> masterFacets(const TriMesh& mesh, const std::string& group) {
  std::vector<std::vector<int>> facets;
  for (const auto& e : facetsInGroup(localIndex(mesh.group(group).nodes, mesh.numNodes()), boundaryEdges(mesh)))
    facets.push_back({e[0], e[1]});
  return facets;
}

std::vector<std::vector<int>> masterFacets(const TetMesh& mesh, const std::string& group) {
  std::vector<std::vector<int>> facets;
  for (const auto& f : facetsInGroup(localIndex(mesh.group(group).nodes, mesh.numNodes()), boundaryTriangles(mesh)))
    facets.push_back({f[0], f[1], f[2]});
  return facets;
}

namespace {

// Outward normal of an oriented boundary facet (node_pairing.hpp, masterFacets), not normalised.
Eigen::VectorXd facetNormal(const Eigen::MatrixXd& positions, const std::vector<int>& facet) {
  const Eigen::VectorXd t = positions.col(facet[1]) - positions.col(facet[0]);
  if (facet.size() == 2) return Eigen::Vector2d(t.y(), -t.x());
  const Eigen::Vector3d a = t, b = positions.col(facet[2]) - positions.col(facet[0]);
  return a.cross(b);
}

// Where the line through x along n meets the facet: its barycentric weights (empty when the line
// misses it or runs along it). The facet's nodes are seen in the plane normal to n, where the line
// is the origin: coordinates y_j = Tᵀ(x_j − x), T a basis of that plane (affine invariance makes any
// basis do), and Σ_j w_j y_j = 0, Σ_j w_j = 1.
std::optional<Eigen::VectorXd> lineMeetsFacet(const Eigen::MatrixXd& positions, const std::vector<int>& facet,
                                              const Eigen::VectorXd& x, const Eigen::VectorXd& n) {
  const Eigen::Index k = static_cast<Eigen::Index>(facet.size()) - 1;  // the plane's dimension, d − 1
  Eigen::MatrixXd basis(n.size(), k);
  basis.col(0) = n.unitOrthogonal();
  if (k == 2) basis.col(1) = Eigen::Vector3d(n).cross(Eigen::Vector3d(basis.col(0)));
  Eigen::MatrixXd y(k, k + 1);
  for (Eigen::Index j = 0; j <= k; ++j) y.col(j) = basis.transpose() * (positions.col(facet[static_cast<size_t>(j)]) - x);
  const Eigen::MatrixXd edges = y.rightCols(k).colwise() - y.col(0);
  const double scale = edges.colwise().norm().maxCoeff();
  if (!(scale > 0.0) || std::abs(edges.determinant()) <= 1e-12 * std::pow(scale, static_cast<double>(k))) return std::nullopt;
  const Eigen::VectorXd mu = edges.partialPivLu().solve(-y.col(0));
  Eigen::VectorXd w(k + 1);
  w[0] = 1.0 - mu.sum();
  w.tail(k) = mu;
  if (w.minCoeff() < kOnTheFacet) return std::nullopt;
  w = (w.array() < kNegligibleWeight).select(0.0, w);
  return w / w.sum();
}

// The pair of slave node x with the point p = Σ_j w_j x_j of `facet`: its nodes of nonzero weight,
// the largest one's as `master`, and n · (x − p) as the gap (negative: p lies on the slave's side).
NodePair facetPair(const Eigen::MatrixXd& positions, const std::vector<int>& facet, const Eigen::VectorXd& w,
                   const Eigen::VectorXd& x, const Eigen::VectorXd& normal) {
  NodePair pair{-1, normal, 0.0, {}, {}};
  Eigen::VectorXd p = Eigen::VectorXd::Zero(x.size());
  for (size_t j = 0; j < facet.size(); ++j) {
    const double weight = w[static_cast<Eigen::Index>(j)];
    p += weight * positions.col(facet[j]);
    if (weight <= 0.0) continue;
    pair.facet.push_back(facet[j]);
    pair.weights.push_back(weight);
  }
  pair.gap = normal.dot(x - p);
  pair.master = pair.facet[static_cast<size_t>(std::max_element(pair.weights.begin(), pair.weights.end()) - pair.weights.begin())];
  return pair;
}

std::string noFacetMessage(const Eigen::MatrixXd& positions, int s) {
  return "slave " + describeNode(positions, s) + " meets no master facet along contact.normal (on the master's side, "
         "facing it): the bodies overlap, contact.normal points from the slave into the master, or the slave boundary "
         "reaches beyond the master's";
}

}  // namespace

std::vector<NodePair> pairNodesToFacets(const Eigen::MatrixXd& positions, const std::vector<int>& slave_nodes,
                                        const std::vector<std::vector<int>>& master_facets,
                                        const Eigen::VectorXd& common_normal) {
  if (master_facets.empty()) throw InputError("the master boundary has no facet");
  Eigen::VectorXd low = positions.col(master_facets.front().front()), high = low;
  for (const auto& facet : master_facets)
    for (int node : facet) {
      low = low.cwiseMin(positions.col(node));
      high = high.cwiseMax(positions.col(node));
    }
  const double extent = (high - low).norm();
  std::vector<NodePair> pairs;
  pairs.reserve(slave_nodes.size());
  for (int s : slave_nodes) {
    const Eigen::VectorXd x = positions.col(s);
    NodePair best;
    double nearest = std::numeric_limits<double>::infinity();
    for (const auto& facet : master_facets) {
      const std::optional<Eigen::VectorXd> w = lineMeetsFacet(positions, facet, x, common_normal);
      if (!w || facetNormal(positions, facet).normalized().dot(common_normal) < kFacingCosineAlongNormal) continue;
      NodePair pair = facetPair(positions, facet, *w, x, common_normal);
      if (pair.gap < -kCoincident * extent || pair.gap >= nearest) continue;
      nearest = pair.gap;
      pair.gap = std::max(pair.gap, 0.0);
      best = std::move(pair);
    }
    if (best.master < 0) throw InputError(noFacetMessage(positions, s));
    pairs.push_back(std::move(best));
  }
  return pairs;
}

}  // namespace stc
