#include "stcontact/studies/mode_localisation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <string>

#include "stcontact/core/input_error.hpp"
#include "stcontact/fem/elasticity.hpp"
#include "stcontact/spacetime/contact_state_table.hpp"

namespace stc {
namespace {

// Distance from p to the segment [a, b] (a point when a = b).
double segmentDistance(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  const Eigen::Vector2d ab = b - a;
  const double length2 = ab.squaredNorm();
  const double s = length2 > 0.0 ? std::clamp((p - a).dot(ab) / length2, 0.0, 1.0) : 0.0;
  return (p - (a + s * ab)).norm();
}

// d_e: centroid of element e to the nearest zone edge, or zone node (a zone may be a single node).
double distanceToZone(const TriMesh& mesh, const ContactZone& zone, const Eigen::Vector2d& p) {
  double d = std::numeric_limits<double>::infinity();
  for (const auto& edge : zone.edges)
    d = std::min(d, segmentDistance(p, mesh.nodes.col(edge[0]), mesh.nodes.col(edge[1])));
  for (int node : zone.nodes) d = std::min(d, (p - mesh.nodes.col(node)).norm());
  return d;
}

}  // namespace

ContactZone ContactZone::everClosed(const Problem& problem, const SolveResult& result) {
  const ContactStateTable states = result.contactStates(problem.contact);
  ContactZone zone;
  std::set<int> closed;
  for (int i = 0; i < problem.contact.size(); ++i)
    for (int k = 0; k < result.interface.numSteps(); ++k)
      if (states.state(i, k) != ContactState::Open) {
        closed.insert(problem.contact.nodes[i]);
        break;
      }
  zone.nodes.assign(closed.begin(), closed.end());
  for (const auto& [name, group] : std::get<TriMesh>(problem.body).groups)
    for (const auto& edge : group.edges)
      if (closed.count(edge[0]) && closed.count(edge[1])) zone.edges.push_back(edge);
  std::sort(zone.edges.begin(), zone.edges.end());
  zone.edges.erase(std::unique(zone.edges.begin(), zone.edges.end()), zone.edges.end());
  if (!zone.nodes.empty()) {
    zone.xmin = zone.xmax = std::get<TriMesh>(problem.body).nodes(0, zone.nodes.front());
    for (int node : zone.nodes) {
      zone.xmin = std::min(zone.xmin, std::get<TriMesh>(problem.body).nodes(0, node));
      zone.xmax = std::max(zone.xmax, std::get<TriMesh>(problem.body).nodes(0, node));
    }
  }
  return zone;
}

ModeLocalisation::ModeLocalisation(const Problem& problem, ContactZone zone, std::vector<double> band_depths)
    : triangles_(std::get<TriMesh>(problem.body).triangles),
      dofs_(std::get<TriMesh>(problem.body).numDofs()),
      hooke_(hookeMatrix(problem.material, problem.plane)),
      zone_(std::move(zone)),
      depths_(std::move(band_depths)) {
  if (zone_.empty())
    throw InputError("mode localisation: the solution never closes a contact node, so there is no contact zone");
  for (double d : depths_)
    if (!(d > 0.0) || !std::isfinite(d))
      throw InputError("mode localisation: band depth " + std::to_string(d) + " must be positive and finite");
  const TriMesh& mesh = std::get<TriMesh>(problem.body);
  const int elements = mesh.numElements();
  strain_.resize(elements);
  area_.resize(elements);
  distance_.resize(elements);
  for (int e = 0; e < elements; ++e) {
    strain_[e] = strainDisplacement(mesh, e);
    area_[e] = 0.5 * mesh.twiceSignedArea(e);
    Eigen::Vector2d centroid = Eigen::Vector2d::Zero();
    for (int a = 0; a < 3; ++a) centroid += mesh.nodes.col(mesh.triangles(a, e)) / 3.0;
    distance_[e] = distanceToZone(mesh, zone_, centroid);
  }
}

Eigen::VectorXd ModeLocalisation::elementEnergies(const Eigen::VectorXd& u) const {
  if (u.size() != dofs_)
    throw InputError("mode localisation: a mode of size " + std::to_string(u.size()) + " for a mesh of " +
                     std::to_string(dofs_) + " dofs");
  Eigen::VectorXd energy(triangles_.cols());
  Eigen::Matrix<double, 6, 1> ue;
  for (Eigen::Index e = 0; e < triangles_.cols(); ++e) {
    for (int a = 0; a < 3; ++a) ue.segment<2>(2 * a) = u.segment<2>(2 * triangles_(a, e));
    const Eigen::Vector3d strain = strain_[e] * ue;  // E_e = A_e εᵀ D ε = Υ_eᵀ K_e Υ_e
    energy[e] = area_[e] * strain.dot(hooke_ * strain);
  }
  return energy;
}

LocalisationMeasure ModeLocalisation::measure(const Eigen::VectorXd& mode) const {
  const Eigen::VectorXd energy = elementEnergies(mode);
  LocalisationMeasure m;
  m.energy = energy.sum();
  const double scale = m.energy > 0.0 ? 1.0 / m.energy : 0.0;
  m.mean_distance = energy.dot(distance_) * scale;
  for (double d : depths_) m.band_share.push_back((distance_.array() <= d).select(energy, 0.0).sum() * scale);
  return m;
}

std::vector<double> ModeLocalisation::bandAreaShares() const {
  std::vector<double> shares;
  const double total = area_.sum();
  for (double d : depths_) shares.push_back((distance_.array() <= d).select(area_, 0.0).sum() / total);
  return shares;
}

}  // namespace stc
