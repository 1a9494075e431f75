#include "src/problem/problem.hpp"

#include <algorithm>
#include <sstream>

#include "src/core/input_error.hpp"
#include "src/fem/elasticity.hpp"
#include "src/fem/load_history.hpp"
#include "src/mesh/gmsh_reader.hpp"
#include "src/mesh/half_disc.hpp"

namespace stc {
namespace {

int componentIndex(Component c) { return c == Component::X ? 0 : 1; }
const char* componentName(Component c) { return c == Component::X ? "x" : "y"; }

std::vector<double> uniformGrid(const TimeSpec& time) {
  std::vector<double> t(time.steps);
  for (int k = 0; k < time.steps; ++k) t[k] = time.end * k / (time.steps - 1);
  return t;
}

// Marks the dofs of every [[dirichlet]] entry; returns, per dof, the entry that prescribes it (−1: free).
std::vector<int> prescribedBy(const Mesh& mesh, const std::vector<DirichletSpec>& dirichlet) {
  std::vector<int> owner(mesh.numDofs(), -1);
  for (std::size_t j = 0; j < dirichlet.size(); ++j) {
    const auto& spec = dirichlet[j];
    for (int node : mesh.group(spec.boundary).nodes) {
      const int dof = 2 * node + componentIndex(spec.component);
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

// Spreads a total force over the boundary's nodes in proportion to their tributary edge length.
Eigen::VectorXd edgeLoadPattern(const Mesh& mesh, const LoadSpec& spec) {
  Eigen::VectorXd f = Eigen::VectorXd::Zero(mesh.numDofs());
  const auto& group = mesh.group(spec.boundary);
  double total = 0.0;
  for (const auto& edge : group.edges) {
    const double length = (mesh.nodes.col(edge[0]) - mesh.nodes.col(edge[1])).norm();
    total += length;
    for (int node : edge) f[2 * node + componentIndex(spec.component)] += 0.5 * length;
  }
  if (!(total > 0.0)) throw InputError("load on boundary '" + spec.boundary + "': the boundary has no edge");
  return f / total;
}

double defaultLengthScale(const Scene& scene, const Mesh& mesh) {
  if (scene.contact.length_scale) return *scene.contact.length_scale;
  if (!scene.mesh.generator.empty()) return scene.mesh.radius;
  return (mesh.nodes.rowwise().maxCoeff() - mesh.nodes.rowwise().minCoeff()).maxCoeff();
}

void addLoads(Problem& p, const Scene& scene, const std::vector<int>& owner) {
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
    p.loads.push_back({restrict(force), pattern, LoadHistory(scene.dirichlet[j].history).sample(p.times)});
  }
  for (const auto& spec : scene.loads)
    p.loads.push_back({restrict(edgeLoadPattern(p.mesh, spec)), Eigen::VectorXd::Zero(p.numDofs()),
                       LoadHistory(spec.history).sample(p.times)});
}

// Runs `step`, prefixing any InputError with the scene file and the key it concerns.
template <class Step>
auto withContext(const Scene& scene, const std::string& key, Step&& step) {
  try {
    return step();
  } catch (const InputError& e) {
    const std::string file = scene.source.empty() ? "<scene>" : scene.source.string();
    throw InputError(file + ": " + (key.empty() ? "" : "key '" + key + "': ") + e.what());
  }
}

}  // namespace

Mesh buildMesh(const MeshSpec& spec) {
  if (!spec.file.empty()) return readGmsh(spec.file);
  if (spec.generator == "half_disc") return makeHalfDisc({spec.radius, spec.arc_nodes, spec.grading});
  throw InputError("mesh generator '" + spec.generator + "' is unknown (known: half_disc)");
}

Problem buildProblem(const Scene& scene) {
  Problem p;
  p.name = scene.name;
  p.mesh = withContext(scene, scene.mesh.file.empty() ? "mesh.generator" : "", [&] { return buildMesh(scene.mesh); });
  p.material = scene.material;
  p.plane = scene.plane;
  p.times = uniformGrid(scene.time);
  p.stiffness = assembleStiffness(p.mesh, hookeMatrix(p.material, p.plane));

  for (std::size_t j = 0; j < scene.dirichlet.size(); ++j)  // name the entry whose boundary is missing
    withContext(scene, "dirichlet[" + std::to_string(j) + "].boundary", [&] { p.mesh.group(scene.dirichlet[j].boundary); });
  for (std::size_t j = 0; j < scene.loads.size(); ++j)
    withContext(scene, "load[" + std::to_string(j) + "].boundary", [&] { p.mesh.group(scene.loads[j].boundary); });
  const std::vector<int> owner = withContext(scene, "dirichlet", [&] { return prescribedBy(p.mesh, scene.dirichlet); });
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
  withContext(scene, "contact.boundary", [&] { return p.mesh.group(scene.contact.boundary); });
  p.contact = withContext(scene, "", [&] {
    return buildContactInterface(p.mesh, scene.contact.boundary, makeObstacle(scene.obstacle), p.free_index,
                                 scene.contact.friction);
  });
  p.length_scale = defaultLengthScale(scene, p.mesh);
  setSearchDirection(p.contact, scene.solver.search_scale, p.material.young, p.length_scale);
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

Eigen::VectorXd Problem::fullDisplacement(const Eigen::VectorXd& u_free, int k) const {
  Eigen::VectorXd u = Eigen::VectorXd::Zero(numDofs());
  for (const auto& term : loads) u += term.values[k] * term.prescribed;
  for (int i = 0; i < numFreeDofs(); ++i) u[free_dofs[i]] = u_free[i];
  return u;
}

}  // namespace stc
