// stcontact._core.Scene: a validated scene (scene_handle.hpp), the sizes `stcontact check` prints,
// the mesh as arrays for plotting, and pickling (its text, source and overrides).
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <stdexcept>

#include "stcontact/core/overloaded.hpp"
#include "stcontact/python/bindings.hpp"
#include "stcontact/python/numpy_arrays.hpp"
#include "stcontact/python/scene_handle.hpp"

namespace stc::python {
namespace {

/// What `stcontact check` prints (cli/check_command.cpp), as numbers.
py::dict checkSizes(const SceneHandle& handle) {
  const Scene& scene = handle.scene();
  const std::shared_ptr<const Problem> problem = handle.problem();
  const Problem& p = *problem;
  const auto& c = p.contact;
  py::dict sizes;
  sizes["scene"] = scene.name;
  sizes["source"] = handle.source().string();
  sizes["dimension"] = p.dimension;
  sizes["plane"] = p.dimension == 3 ? "none" : p.plane == PlaneModel::Strain ? "strain" : "stress";
  sizes["young"] = p.material.young;
  sizes["poisson"] = p.material.poisson;
  sizes["friction"] = c.friction;
  sizes["nodes"] = p.numNodes();
  sizes["elements"] = p.numElements();
  sizes["dofs"] = p.numDofs();
  sizes["free_dofs"] = p.numFreeDofs();
  sizes["prescribed_dofs"] = p.numDofs() - p.numFreeDofs();
  sizes["contact_nodes"] = c.size();
  sizes["interface_rows"] = c.rows();
  sizes["boundary"] = scene.contact.boundary;
  sizes["instants"] = p.numSteps();
  sizes["t_start"] = p.times.front();
  sizes["t_end"] = p.times.back();
  sizes["initial_gap_min"] = c.initial_gap.minCoeff();
  sizes["initial_gap_max"] = c.initial_gap.maxCoeff();
  sizes["kappa"] = scene.search_direction.scale;
  sizes["length_scale"] = p.length_scale;
  sizes["kappa_young_per_length"] = c.search_scale_per_length;
  sizes["search_direction_min"] = c.search_direction.minCoeff();
  sizes["search_direction_max"] = c.search_direction.maxCoeff();
  sizes["solver"] = std::string(scene.solver.name());
  sizes["tolerance"] = scene.solver.tolerance();
  return sizes;
}

/// The mesh and the contact interface as arrays: nodes (N × d), triangles (E × 3, counter-clockwise
/// node ids; 2D) or tetrahedra (E × 4, positive volume; 3D), contact_nodes (n_C mesh node ids, in the order of the interface rows),
/// master_nodes (two bodies: the master node paired with each, else empty), master_facets and
/// master_weights (two bodies: n_C × k, the master nodes each is compared with, −1 padded, and their
/// weights; k = 1 node to node, d node to segment; else 0 × 0), initial_gap (n_C), search_direction
/// (d n_C: k per interface row), times (m).
py::dict meshArrays(const SceneHandle& handle) {
  const std::shared_ptr<const Problem> problem = handle.problem();
  py::dict mesh;
  mesh["nodes"] = movedToNumpy(Eigen::MatrixXd(problem->nodePositions().transpose()));
  std::visit(Overloaded{[&](const TriMesh& m) { mesh["triangles"] = movedToNumpy(Eigen::MatrixXi(m.triangles.transpose())); },
                        [&](const TetMesh& m) { mesh["tetrahedra"] = movedToNumpy(Eigen::MatrixXi(m.tets.transpose())); }},
             problem->body);
  mesh["contact_nodes"] = movedToNumpy(std::vector<int>(problem->contact.nodes));
  mesh["master_nodes"] = movedToNumpy(std::vector<int>(problem->contact.master_nodes));
  mesh["master_facets"] = movedToNumpy(Eigen::MatrixXi(problem->contact.master_facets.transpose()));
  mesh["master_weights"] = movedToNumpy(Eigen::MatrixXd(problem->contact.master_weights.transpose()));
  mesh["initial_gap"] = movedToNumpy(Eigen::VectorXd(problem->contact.initial_gap));
  mesh["search_direction"] = movedToNumpy(Eigen::VectorXd(problem->contact.search_direction));
  mesh["times"] = movedToNumpy(std::vector<double>(problem->times));
  return mesh;
}

}  // namespace

py::tuple sceneState(const SceneHandle& scene) {
  return py::make_tuple(scene.text(), scene.source().string(), scene.overrides());
}

SceneHandle sceneFromState(const py::tuple& state) {
  if (state.size() != 3) throw std::invalid_argument("a pickled scene holds (text, source, sets)");
  return SceneHandle::fromText(state[0].cast<std::string>(), state[1].cast<std::string>(),
                               state[2].cast<std::vector<std::string>>());
}

void bindScene(py::module_& module) {
  py::class_<SceneHandle>(module, "Scene", "A validated scene (TOML text, source, --set overrides).")
      .def_static("from_file", &SceneHandle::fromFile, py::arg("path"), py::arg("sets"))
      .def_static("from_toml", &SceneHandle::fromText, py::arg("text"), py::arg("source"), py::arg("sets"))
      .def("with_sets", &SceneHandle::withOverrides, py::arg("sets"))
      .def_property_readonly("name", [](const SceneHandle& h) { return h.scene().name; })
      .def_property_readonly("source", [](const SceneHandle& h) { return h.source().string(); })
      .def_property_readonly("text", &SceneHandle::text)
      .def_property_readonly("sets", &SceneHandle::overrides)
      .def_property_readonly("parameters_json", [](const SceneHandle& h) { return h.scene().parameters_json; })
      .def_property_readonly("solver", [](const SceneHandle& h) { return std::string(h.scene().solver.name()); })
      .def("check", &checkSizes)
      .def("mesh", &meshArrays)
      .def(py::pickle(&sceneState, &sceneFromState));
}

}  // namespace stc::python
