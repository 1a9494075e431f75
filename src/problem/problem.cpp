#include "stcontact/problem/problem.hpp"

#include <algorithm>
#include <sstream>

#include "stcontact/core/input_error.hpp"
#include "stcontact/core/missing_file_error.hpp"
#include "stcontact/core/overloaded.hpp"
#include "stcontact/fem/elasticity.hpp"
#include "stcontact/fem/elasticity_3d.hpp"
#include "stcontact/fem/load_history.hpp"
#include "stcontact/mesh/connected_parts.hpp"
#include "stcontact/mesh/facet_measure.hpp"
#include "stcontact/mesh/gmsh_reader.hpp"
#include "stcontact/mesh/half_ball.hpp"
#include "stcontact/mesh/half_disc.hpp"
#include "stcontact/mesh/half_disc_slab.hpp"
#include "stcontact/mesh/mirror_image.hpp"
#include "stcontact/problem/distributed_loads.hpp"
#include "stcontact/problem/representable_scales.hpp"
#include "stcontact/problem/rigid_motions.hpp"
#include "stcontact/problem/size_estimate.hpp"

namespace stc {
namespace {

const char* componentName(Component c) { return c == Component::X ? "x" : c == Component::Y ? "y" : "z"; }

std::vector<double> uniformGrid(const TimeSpec& time) {
  std::vector<double> t(time.steps);
  for (int k = 0; k < time.steps; ++k) t[k] = time.end * k / (time.steps - 1);
  return t;
}

// Marks the dofs of every [[dirichlet]] entry; returns, per dof, the entry that prescribes it (−1: free).
template <class MeshT>
std::vector<int> prescribedBy(const MeshT& mesh, const std::vector<DirichletSpec>& dirichlet) {
  const int dim = static_cast<int>(mesh.nodes.rows());
  std::vector<int> owner(mesh.numDofs(), -1);
  for (std::size_t j = 0; j < dirichlet.size(); ++j) {
    const auto& spec = dirichlet[j];
    for (int node : mesh.group(spec.boundary).nodes) {
      const int dof = dim * node + componentIndex(spec.component);
      if (owner[dof] >= 0) {
        std::ostringstream msg;
        msg << "dirichlet[" << j << "]: component " << componentName(spec.component) << " of node " << node
            << " on boundary '" << spec.boundary << "' is already prescribed by dirichlet[" << owner[dof] << "]";
        throw InputError(msg.str());
      }
      owner[dof] = static_cast<int>(j);
    }
  }
  return owner;
}

// Spreads a total force over the boundary's nodes in proportion to their tributary measure
// (an equal share of each edge's length in 2D, of each triangle's area in 3D).
template <class Facet>
Eigen::VectorXd facetLoadPattern(const Eigen::MatrixXd& x, const std::vector<Facet>& facets, const LoadSpec& spec) {
  const int dim = static_cast<int>(x.rows());
  Eigen::VectorXd f = Eigen::VectorXd::Zero(dim * x.cols());
  const double share = 1.0 / static_cast<double>(std::tuple_size_v<Facet>);
  double total = 0.0;
  for (const auto& facet : facets) {
    const double measure = facetMeasure(x, facet);
    total += measure;
    for (int node : facet) f[dim * node + componentIndex(spec.component)] += share * measure;
  }
  if (!(total > 0.0))
    throw InputError("load on boundary '" + spec.boundary + "': the boundary has no " + (dim == 3 ? "face" : "edge"));
  return f / total;
}

// A boundary group's facets: edges in 2D, triangles in 3D.
const std::vector<std::array<int, 2>>& facetsOf(const BoundaryGroup& group) { return group.edges; }
const std::vector<std::array<int, 3>>& facetsOf(const SurfaceGroup& group) { return group.triangles; }

Eigen::VectorXd loadPattern(const Problem& p, const LoadSpec& spec) {
  return std::visit(
      [&](const auto& m) -> Eigen::VectorXd {
        if (spec.kind == LoadKind::Pressure) return pressurePattern(m, spec.boundary);
        if (spec.kind == LoadKind::Body) return bodyForcePattern(m, spec.component);
        return facetLoadPattern(m.nodes, facetsOf(m.group(spec.boundary)), spec);
      },
      p.body);
}

// The mesh with only its elements e of flag[e] == keep (the same nodes and groups).
template <class Mesh>
Mesh withElements(const Mesh& mesh, const std::vector<char>& flag, char keep) {
  std::vector<Eigen::Index> kept;
  for (int e = 0; e < mesh.numElements(); ++e)
    if (flag[static_cast<std::size_t>(e)] == keep) kept.push_back(e);
  Mesh part = mesh;
  elementNodes(part) = elementNodes(mesh)(Eigen::all, kept);
  return part;
}

Eigen::SparseMatrix<double> stiffnessOf(const BodyMesh& body, const MaterialSpec& material, PlaneModel plane) {
  return std::visit(Overloaded{[&](const TriMesh& m) { return assembleStiffness(m, hookeMatrix(material, plane)); },
                               [&](const TetMesh& m) { return assembleStiffness(m, hookeMatrix3d(material)); }},
                    body);
}

// K = Σ_e K_e with each element's material: the slave body's (and one body's) `material`, the
// master body's `master_material` on its elements.
Eigen::SparseMatrix<double> stiffnessOf(const Problem& p) {
  if (!p.master_material) return stiffnessOf(p.body, p.material, p.plane);
  const auto part = [&](char master) {
    return std::visit([&](const auto& m) { return BodyMesh(withElements(m, p.master_elements, master)); }, p.body);
  };
  return stiffnessOf(part(0), p.material, p.plane) + stiffnessOf(part(1), *p.master_material, p.plane);
}

// Per element, 1 when it belongs to the body of the boundary group `master`.
std::vector<char> elementsOfBodyOf(const BodyMesh& body, const std::string& master) {
  const std::vector<int> part = partOfNodes(body);
  return std::visit([&](const auto& m) {
    const int master_part = part[m.group(master).nodes.front()];
    const auto& elements = elementNodes(m);
    std::vector<char> flag(static_cast<std::size_t>(elements.cols()));
    for (Eigen::Index e = 0; e < elements.cols(); ++e) flag[e] = part[elements(0, e)] == master_part ? 1 : 0;
    return flag;
  }, body);
}

/// R, the body's size (the default of L): the generator's radius, else half the mesh's largest
/// extent, which is the radius again for a half-disc or half-ball read from a file (its extent is
/// 2R), so that the same body gets the same search direction however it was meshed.
double bodySize(const ModelSpec& scene, const Problem& p) {
  if (!scene.mesh.generator.empty()) return scene.mesh.radius;
  Eigen::MatrixXd x = p.nodePositions();
  if (scene.mesh.mirror_gap) x = x.leftCols(x.cols() / 2).eval();  // one body (mesh/mirror_image.hpp)
  return 0.5 * (x.rowwise().maxCoeff() - x.rowwise().minCoeff()).maxCoeff();
}

/// The search direction k = κ E ℓ_i / L scaled to the body, κ R / L, must lie in
/// [kMinSearchScale, kMaxSearchScale]: LATIN's contraction rate tends to 1 at both ends
/// (docs/search_direction.md: κ ≤ 0.03 needs ≥ 2700 iterations to true error 1e-6 on the seed
/// scene, κ = 100 needs 1152, against 97 at κ = 4), and beyond them the iterates move by less than
/// the error estimate can resolve: it reported "converged" at true errors above 1 (L = 1e-4 R,
/// L = 1e-12 R). The hard cases kappa_0.01 and kappa_100 sit at the ends.
constexpr double kMinSearchScale = 1e-2;
constexpr double kMaxSearchScale = 1e2;

void requireMeaningfulSearchDirection(const ModelSpec& scene, double size, double length_scale) {
  const double kappa = scene.search_direction.scale;
  const double scaled = kappa * size / length_scale;
  if (scaled >= kMinSearchScale && scaled <= kMaxSearchScale) return;
  std::ostringstream msg;
  msg << "the search direction's scale κ R / L = " << scaled << " (κ = solver.search_scale = " << kappa
      << ", L = contact.length_scale = " << length_scale << ", R = the body's size = " << size
      << ") must be in [" << kMinSearchScale << ", " << kMaxSearchScale
      << "]: beyond it LATIN's iterates move by less than the error estimate can resolve "
         "(docs/search_direction.md)";
  throw InputError(msg.str());
}

void addLoads(Problem& p, const ModelSpec& scene, const std::vector<int>& owner) {
  const Eigen::SparseMatrix<double>& K = p.stiffness;
  auto restrict = [&](const Eigen::VectorXd& full) {
    Eigen::VectorXd out(p.numFreeDofs());
    for (int i = 0; i < p.numFreeDofs(); ++i) out[i] = full[p.free_dofs[i]];
    return out;
  };
  for (std::size_t j = 0; j < scene.dirichlet.size(); ++j) {
    Eigen::VectorXd pattern = Eigen::VectorXd::Zero(p.numDofs());
    for (int dof = 0; dof < p.numDofs(); ++dof)
      if (owner[dof] == static_cast<int>(j)) pattern[dof] = 1.0;
    const Eigen::VectorXd force = -(K * pattern);  // −K_fD e_D on the free rows
    std::vector<double> values = LoadHistory(scene.dirichlet[j].history).sample(p.times);
    if (p.frame_motion.size() > 0)  // u_d − d(t): in the obstacle's frame (Problem::frame_motion)
      for (int k = 0; k < p.numSteps(); ++k) values[k] -= p.frame_motion(componentIndex(scene.dirichlet[j].component), k);
    p.loads.push_back({restrict(force), pattern, std::move(values)});
  }
  for (const auto& spec : scene.loads)
    p.loads.push_back({restrict(loadPattern(p, spec)), Eigen::VectorXd::Zero(p.numDofs()),
                       LoadHistory(spec.history).sample(p.times)});
}

// The Dirichlet conditions must hold every rigid motion (problem/rigid_motions.hpp); otherwise the
// message names the free ones and the boundaries that could hold them.
void requireHeldBody(const BodyMesh& body, const std::vector<int>& owner) {
  std::vector<char> prescribed(owner.size());
  for (std::size_t dof = 0; dof < owner.size(); ++dof) prescribed[dof] = owner[dof] >= 0;
  const std::vector<std::string> free = freeRigidMotions(body, prescribed);
  if (free.empty()) return;
  std::string motions, boundaries;
  for (const std::string& m : free) motions += (motions.empty() ? "" : "; ") + m;
  std::visit([&](const auto& mesh) {
    for (const auto& [name, group] : mesh.groups) boundaries += (boundaries.empty() ? "'" : ", '") + name + "'";
  }, body);
  throw InputError("the conditions leave the body free to move rigidly (" + motions +
                   "): K_ff is singular and the equilibrium not unique, as contact and friction cannot hold a "
                   "rigid motion; prescribe it on a boundary (the mesh has " + boundaries + ")");
}

// Per dof: prescribed by a [[dirichlet]] entry whose history is 0 at every instant (addLoads has
// sampled the entries' histories, in order, as the first load terms).
std::vector<char> heldAtZero(const Problem& p, const std::vector<int>& owner) {
  std::vector<char> zero(p.numDofs(), 0);
  for (int dof = 0; dof < p.numDofs(); ++dof) {
    if (owner[dof] < 0) continue;
    const std::vector<double>& values = p.loads[owner[dof]].values;
    zero[dof] = std::all_of(values.begin(), values.end(), [](double v) { return v == 0.0; });
  }
  return zero;
}

// `message` prefixed with the scene file and the key it concerns.
std::string inContext(const ModelSpec& scene, const std::string& key, const std::string& message) {
  const std::string file = scene.source.empty() ? "<scene>" : scene.source.string();
  return file + ": " + (key.empty() ? "" : "key '" + key + "': ") + message;
}

// Runs `step`, prefixing any InputError with the scene file and the key it concerns; a missing
// file stays a MissingFileError.
template <class Step>
auto withContext(const ModelSpec& scene, const std::string& key, Step&& step) {
  try {
    return step();
  } catch (const MissingFileError& e) {
    throw MissingFileError(inContext(scene, key, e.what()), e.path());
  } catch (const InputError& e) {
    throw InputError(inContext(scene, key, e.what()));
  }
}

// A plane's point and normal, a ball's centre, have the scene's dimension (a polyline's points and a
// surface's file are checked by the reader; two bodies have no obstacle). Scenes built in code skip
// the reader.
void requireObstacleDimension(const ModelSpec& scene) {
  const ObstacleSpec& o = scene.obstacle;
  const int d = scene.dimension;
  if (!scene.contact.master.empty() || o.type == ObstacleType::Polyline || o.type == ObstacleType::Surface) return;
  const bool plane = o.type == ObstacleType::Plane;
  if (plane ? (o.point.size() == d && o.normal.size() == d) : o.centre.size() == d) return;
  throw InputError(std::string(plane ? "point and normal" : "centre") + " must have " + std::to_string(d) +
                   " entries in a " + std::to_string(d) + "D scene");
}

// d(t_k) of the obstacle's [[obstacle.motion]] entries, d × m; empty when it has none or they are
// zero at every instant (a fixed obstacle: the problem stays as it was).
Eigen::MatrixXd obstacleMotion(const ModelSpec& scene, const std::vector<double>& times) {
  Eigen::MatrixXd d = Eigen::MatrixXd::Zero(scene.dimension, static_cast<Eigen::Index>(times.size()));
  if (!scene.contact.master.empty()) return {};
  for (const ObstacleMotionSpec& motion : scene.obstacle.motion) {
    const std::vector<double> values = LoadHistory(motion.history).sample(times);
    d.row(componentIndex(motion.component)) += Eigen::Map<const Eigen::RowVectorXd>(values.data(), d.cols());
  }
  if (d.cwiseAbs().maxCoeff() == 0.0) return {};
  return d;
}

// The rigid obstacle's interface, or the two bodies' node-to-node pairs (contact.master).
ContactInterface contactInterfaceOf(const ModelSpec& scene, const Problem& p, const std::vector<char>& zero) {
  const DofStatus dofs{p.free_index, zero};
  const ContactSpec& c = scene.contact;
  if (!c.master.empty())
    return std::visit([&](const auto& mesh) { return buildContactPair(mesh, c.boundary, c.master, c.normal, c.to_segment, dofs, c.friction); },
                      p.body);
  const Obstacle obstacle = makeObstacle(scene.obstacle);  // a surface's file is read here
  return std::visit([&](const auto& mesh) { return buildContactInterface(mesh, c.boundary, obstacle, dofs, c.friction); },
                    p.body);
}

// ν within [kPoissonLow, kPoissonHigh] (src/scene/model_spec.hpp), worded as the scene reader words it.
void requirePoissonInRange(const MaterialSpec& material, const char* key) {
  if (material.poisson >= kPoissonLow && material.poisson <= kPoissonHigh) return;
  std::ostringstream msg;
  msg << "key '" << key << "' = " << material.poisson
      << " is out of range: must be in [-0.999999, 0.4999995] (1 + ν and 1 - 2ν at least 1e-6)";
  throw InputError(msg.str());
}

}  // namespace

BodyMesh buildBodyMesh(const MeshSpec& spec, int dimension) {
  if (spec.mirror_gap) {
    MeshSpec body = spec;
    body.mirror_gap.reset();
    return withMirrorImage(buildBodyMesh(body, dimension), *spec.mirror_gap);
  }
  if (dimension == 3) {
    if (!spec.file.empty()) return readGmsh3d(spec.file);
    if (spec.generator == "half_ball") return makeHalfBall({spec.radius, spec.divisions, spec.grading, spec.core});
    if (spec.generator == "half_disc_slab")
      return makeHalfDiscSlab({{spec.radius, spec.arc_nodes, spec.grading}, spec.thickness, spec.layers});
    throw InputError("mesh generator '" + spec.generator + "' is unknown (known in 3D: half_ball, half_disc_slab)");
  }
  if (!spec.file.empty()) return readGmsh(spec.file);
  if (spec.generator == "half_disc") return makeHalfDisc({spec.radius, spec.arc_nodes, spec.grading});
  throw InputError("mesh generator '" + spec.generator + "' is unknown (known in 2D: half_disc)");
}

Problem buildProblem(const ModelSpec& scene) {
  Problem p;
  p.name = scene.name;
  p.dimension = scene.dimension;
  withContext(scene, "obstacle", [&] { requireObstacleDimension(scene); });
  withContext(scene, "", [&] { requireFitsInMemory(scene); });  // before the mesh is built
  const std::string mesh_key = scene.mesh.file.empty() ? "mesh.generator" : "";
  p.body = withContext(scene, mesh_key, [&] { return buildBodyMesh(scene.mesh, p.dimension); });
  p.material = scene.material;
  requirePoissonInRange(scene.material, "material.poisson");  // a scene built in code skips the reader
  if (scene.master_material) requirePoissonInRange(*scene.master_material, "master_material.poisson");
  if (!scene.contact.master.empty())  // before the master body's elements are looked up
    withContext(scene, "contact.master", [&] { requireGroup(p.body, scene.contact.master); });
  if (scene.master_material) {
    p.master_material = scene.master_material;
    p.master_elements = elementsOfBodyOf(p.body, scene.contact.master);
  }
  p.plane = scene.plane;
  p.times = uniformGrid(scene.time);
  p.frame_motion = obstacleMotion(scene, p.times);
  p.stiffness = stiffnessOf(p);
  const auto group = [&](const std::string& name) { requireGroup(p.body, name); };
  for (std::size_t j = 0; j < scene.dirichlet.size(); ++j)  // name the entry whose boundary is missing
    withContext(scene, "dirichlet[" + std::to_string(j) + "].boundary", [&] { group(scene.dirichlet[j].boundary); });
  for (std::size_t j = 0; j < scene.loads.size(); ++j)
    if (scene.loads[j].kind != LoadKind::Body)
      withContext(scene, "load[" + std::to_string(j) + "].boundary", [&] { group(scene.loads[j].boundary); });
  const std::vector<int> owner = withContext(scene, "dirichlet", [&] {
    return std::visit([&](const auto& mesh) { return prescribedBy(mesh, scene.dirichlet); }, p.body);
  });
  withContext(scene, "dirichlet", [&] { requireHeldBody(p.body, owner); });
  p.free_index.assign(p.numDofs(), -1);
  for (int dof = 0; dof < p.numDofs(); ++dof)
    if (owner[dof] < 0) {
      p.free_index[dof] = static_cast<int>(p.free_dofs.size());
      p.free_dofs.push_back(dof);
    }
  if (p.free_dofs.empty()) withContext(scene, "dirichlet", [] { throw InputError("every dof is prescribed: nothing to solve"); });
  std::vector<Eigen::Triplet<double>> triplets;
  for (int col = 0; col < p.stiffness.outerSize(); ++col)
    for (Eigen::SparseMatrix<double>::InnerIterator it(p.stiffness, col); it; ++it)
      if (p.free_index[it.row()] >= 0 && p.free_index[it.col()] >= 0)
        triplets.emplace_back(p.free_index[it.row()], p.free_index[it.col()], it.value());
  p.stiffness_free.resize(p.numFreeDofs(), p.numFreeDofs());
  p.stiffness_free.setFromTriplets(triplets.begin(), triplets.end());

  withContext(scene, "load", [&] { addLoads(p, scene, owner); });
  withContext(scene, "contact.boundary", [&] { group(scene.contact.boundary); });
  p.contact = withContext(scene, "", [&] { return contactInterfaceOf(scene, p, heldAtZero(p, owner)); });
  withContext(scene, "", [&] { requireRepresentableScales(scene, p); });
  const double size = bodySize(scene, p);
  p.length_scale = scene.contact.length_scale.value_or(size);
  withContext(scene, "", [&] { requireMeaningfulSearchDirection(scene, size, p.length_scale); });
  // Two materials: E of k = κ E ℓ / L is their harmonic mean, the stiffness of the two bodies in series
  // scaled so that equal materials give E (docs/two_bodies.md).
  const double young = p.master_material ? 2.0 / (1.0 / p.material.young + 1.0 / p.master_material->young)
                                         : p.material.young;
  setSearchDirection(p.contact, scene.search_direction.scale, young, p.length_scale, scene.search_direction.law);
  return p;
}

Eigen::VectorXd Problem::load(int k) const {
  Eigen::VectorXd f = Eigen::VectorXd::Zero(numFreeDofs());
  for (const auto& term : loads) f += term.values[k] * term.free_force;
  return f;
}

Eigen::MatrixXd Problem::loadBlock(int k0, int count) const {
  Eigen::MatrixXd F = Eigen::MatrixXd::Zero(numFreeDofs(), count);
  for (const auto& term : loads) {
    const Eigen::Map<const Eigen::RowVectorXd> values(term.values.data() + k0, count);
    F.noalias() += term.free_force * values;
  }
  return F;
}

void Problem::addFrameMotion(Eigen::Ref<Eigen::VectorXd> u, int k) const {
  if (frame_motion.size() == 0) return;
  for (int node = 0; node < numNodes(); ++node) u.segment(dimension * node, dimension) += frame_motion.col(k);
}

Eigen::VectorXd Problem::absoluteDisplacement(const Eigen::VectorXd& u_free, int k) const {
  Eigen::VectorXd u = fullDisplacement(u_free, k);
  addFrameMotion(u, k);
  return u;
}

Eigen::VectorXd Problem::fullDisplacement(const Eigen::VectorXd& u_free, int k) const {
  Eigen::VectorXd u = Eigen::VectorXd::Zero(numDofs());
  for (const auto& term : loads) u += term.values[k] * term.prescribed;
  for (int i = 0; i < numFreeDofs(); ++i) u[free_dofs[i]] = u_free[i];
  return u;
}

}  // namespace stc
