#include "stcontact/scene/scene_reader.hpp"

#include <toml++/toml.h>

#include <cmath>
#include <fstream>
#include <initializer_list>
#include <span>
#include <sstream>
#include <utility>

#include "stcontact/core/input_error.hpp"
#include "stcontact/scene/detail/guarded_parse.hpp"
#include "stcontact/scene/detail/scene_errors.hpp"
#include "stcontact/scene/detail/scene_overrides.hpp"
#include "stcontact/scene/detail/table_view.hpp"

namespace stc {

namespace {

using detail::ErrorReporter;
using detail::formatNumber;
using detail::TableView;

/// Reads a string key that must be one of `allowed`; returns it.
std::string readKeyword(const TableView& table, std::string_view key, std::span<const std::string_view> allowed) {
  std::string text = table.requiredString(key);
  std::string list;
  for (const auto name : allowed) {
    if (name == text) return text;
    list += (list.empty() ? "\"" : ", \"") + std::string(name) + "\"";
  }
  const std::string path = table.keyPath(key);
  table.errors().fail(path, "key '" + path + "' = \"" + text + "\" is not one of " + list);
}

std::string readKeyword(const TableView& table, std::string_view key,
                        std::initializer_list<std::string_view> allowed) {
  return readKeyword(table, key, std::span<const std::string_view>(allowed.begin(), allowed.size()));
}

/// Reads a Component: "x" or "y", and "z" in a 3D scene.
Component readComponent(const TableView& table, int dimension) {
  const std::string name =
      dimension == 3 ? readKeyword(table, "component", {"x", "y", "z"}) : readKeyword(table, "component", {"x", "y"});
  return name == "x" ? Component::X : name == "y" ? Component::Y : Component::Z;
}

/// Throws "key 'P' = V is out of range: must be RULE" unless `ok`.
void requireRange(const TableView& table, std::string_view key, double value, bool ok,
                  std::string_view rule) {
  if (!ok) table.errors().outOfRange(table.keyPath(key), formatNumber(value), rule);
}

/// A nonempty string (boundary names, the scene name).
std::string requiredName(const TableView& table, std::string_view key) {
  std::string name = table.requiredString(key);
  if (name.empty()) {
    const std::string path = table.keyPath(key);
    table.errors().fail(path, "key '" + path + "' must not be empty");
  }
  return name;
}

/// `dimension` finite numbers [x, y] or [x, y, z].
Eigen::VectorXd readVector(const TableView& table, std::string_view key, int dimension) {
  const std::vector<double> x = table.requiredNumbers(key);
  if (static_cast<int>(x.size()) != dimension) {
    const std::string path = table.keyPath(key);
    table.errors().fail(path, "key '" + path + "' must have " + std::to_string(dimension) + " entries " +
                                  (dimension == 3 ? "[x, y, z]" : "[x, y]") + ", got " + std::to_string(x.size()));
  }
  return Eigen::Map<const Eigen::VectorXd>(x.data(), dimension);
}

/// `dimension = 2` (default) or 3.
int readDimension(const TableView& root) {
  const int dimension = root.optionalInt("dimension").value_or(2);
  requireRange(root, "dimension", dimension, dimension == 2 || dimension == 3, "must be 2 or 3");
  return dimension;
}

/// The scene name becomes a folder of the default output path, so it must be a plain name.
std::string readName(const TableView& root) {
  std::string name = requiredName(root, "name");
  if (name.find_first_of("/\\") != std::string::npos || name == "." || name == "..") {
    root.errors().fail("name", "key 'name' = \"" + name +
                                   "\" must be a plain file name (no '/', '\\', '.' or '..')");
  }
  return name;
}

PlaneModel readModel(const TableView& root, int dimension) {
  const auto model = root.optionalTable("model", {"plane"});
  if (!model) return PlaneModel::Strain;
  if (dimension == 3) root.errors().fail("model", "table [model] (plane strain or stress) applies to 2D scenes only");
  if (!model->has("plane")) return PlaneModel::Strain;
  return readKeyword(*model, "plane", {"strain", "stress"}) == "strain" ? PlaneModel::Strain
                                                                        : PlaneModel::Stress;
}

// The built-in generators and their keys besides `radius` (src/mesh/half_disc.hpp, half_ball.hpp,
// half_disc_slab.hpp); a key of another generator is refused naming the generators that take it.
struct GeneratorKeys {
  std::string_view name;
  int dimension;
  std::vector<std::string_view> keys;
};
const GeneratorKeys kGenerators[] = {{"half_disc", 2, {"arc_nodes", "grading"}},
                                     {"half_ball", 3, {"divisions", "grading", "core"}},
                                     {"half_disc_slab", 3, {"arc_nodes", "grading", "thickness", "layers"}}};
const std::string_view kGeneratorKeys[] = {"radius", "arc_nodes", "grading", "divisions", "core", "thickness", "layers"};

bool takes(const GeneratorKeys& g, std::string_view key) {
  return key == "radius" || std::find(g.keys.begin(), g.keys.end(), key) != g.keys.end();
}

// "\"half_disc\" or \"half_disc_slab\"": the generators that take `key`.
std::string ownersOf(std::string_view key) {
  std::string out;
  for (const GeneratorKeys& g : kGenerators)
    if (takes(g, key)) out += (out.empty() ? "\"" : " or \"") + std::string(g.name) + "\"";
  return out;
}

void refuseForeignKey(const TableView& mesh, std::string_view key, const std::string& suffix) {
  if (mesh.has(key))
    mesh.errors().fail(mesh.keyPath(key), "key '" + mesh.keyPath(key) + "' applies to generator = " + ownersOf(key) + suffix);
}

void readGenerator(const TableView& mesh, MeshSpec& spec) {
  const GeneratorKeys& g = *std::find_if(std::begin(kGenerators), std::end(kGenerators),
                                         [&](const GeneratorKeys& k) { return k.name == spec.generator; });
  for (std::string_view key : kGeneratorKeys)
    if (!takes(g, key)) refuseForeignKey(mesh, key, "");
  spec.radius = mesh.optionalNumber("radius").value_or(spec.radius);
  requireRange(mesh, "radius", spec.radius, spec.radius > 0.0, "must be > 0");
  if (takes(g, "arc_nodes")) {
    spec.arc_nodes = mesh.optionalInt("arc_nodes").value_or(spec.arc_nodes);
    requireRange(mesh, "arc_nodes", spec.arc_nodes, spec.arc_nodes >= 3, "must be >= 3");
  }
  if (takes(g, "divisions")) {
    spec.divisions = mesh.optionalInt("divisions").value_or(spec.divisions);
    requireRange(mesh, "divisions", spec.divisions, spec.divisions >= 2, "must be >= 2");
    spec.core = mesh.optionalNumber("core").value_or(spec.core);
    requireRange(mesh, "core", spec.core, spec.core == 0.0 || (spec.core > 0.0 && spec.core < 1.0),
                 "must be 0 (no core) or in (0, 1)");
  }
  if (takes(g, "layers")) {
    spec.thickness = mesh.optionalNumber("thickness").value_or(spec.thickness);
    requireRange(mesh, "thickness", spec.thickness, spec.thickness > 0.0, "must be > 0");
    spec.layers = mesh.optionalInt("layers").value_or(spec.layers);
    requireRange(mesh, "layers", spec.layers, spec.layers >= 1, "must be >= 1");
  }
  const bool ball = g.name == "half_ball";
  spec.grading = mesh.optionalNumber("grading").value_or(ball ? 1.5 : spec.grading);
  requireRange(mesh, "grading", spec.grading, spec.grading >= 1.0 && spec.grading <= (ball ? 2.0 : 4.0),
               ball ? "must be in [1, 2] (1 = uniform)" : "must be in [1, 4] (1 = uniform)");
}

MeshSpec readMesh(const TableView& root, const std::filesystem::path& source, int dimension) {
  const TableView mesh = root.requiredTable(
      "mesh", {"generator", "file", "radius", "arc_nodes", "grading", "divisions", "core", "thickness", "layers"});
  const ErrorReporter& errors = mesh.errors();
  const bool hasGenerator = mesh.has("generator");
  if (hasGenerator == mesh.has("file")) {
    errors.fail("mesh", hasGenerator
                            ? "keys 'mesh.generator' and 'mesh.file' exclude each other: give one"
                            : "missing required key 'mesh.generator' or 'mesh.file' (give one)");
  }
  MeshSpec spec;
  if (hasGenerator) {
    spec.generator = dimension == 3 ? readKeyword(mesh, "generator", {"half_ball", "half_disc_slab"})
                                    : readKeyword(mesh, "generator", {"half_disc"});
    readGenerator(mesh, spec);
    return spec;
  }
  for (std::string_view key : kGeneratorKeys) refuseForeignKey(mesh, key, ", not to a mesh file");
  const std::filesystem::path file = requiredName(mesh, "file");
  spec.file = file.is_absolute() ? file : (source.parent_path() / file).lexically_normal();
  return spec;
}

MaterialSpec readMaterial(const TableView& root) {
  const TableView material = root.requiredTable("material", {"young", "poisson"});
  MaterialSpec spec;
  spec.young = material.requiredNumber("young");
  requireRange(material, "young", spec.young, spec.young > 0.0, "must be > 0");
  spec.poisson = material.requiredNumber("poisson");
  requireRange(material, "poisson", spec.poisson, spec.poisson > -1.0 && spec.poisson < 0.5,
               "must be in (-1, 0.5)");
  return spec;
}

ObstacleSpec readObstacle(const TableView& root, int dimension) {
  const TableView obstacle = root.requiredTable("obstacle", {"type", "point", "normal"});
  ObstacleSpec spec;
  if (obstacle.has("type")) readKeyword(obstacle, "type", {"plane"});
  spec.type = ObstacleType::Plane;
  spec.point = readVector(obstacle, "point", dimension);
  const Eigen::VectorXd normal = readVector(obstacle, "normal", dimension);
  const double length = normal.norm();
  if (!(length > 0.0) || !std::isfinite(length)) {
    std::string entries;
    for (double x : normal) entries += (entries.empty() ? "" : ", ") + formatNumber(x);
    obstacle.errors().fail(obstacle.keyPath("normal"),
                           "key 'obstacle.normal' = [" + entries + "] must be a nonzero finite vector");
  }
  spec.normal = normal / length;
  return spec;
}

ContactSpec readContact(const TableView& root) {
  const TableView contact = root.requiredTable("contact", {"boundary", "friction", "length_scale"});
  ContactSpec spec;
  spec.boundary = requiredName(contact, "boundary");
  spec.friction = contact.requiredNumber("friction");
  requireRange(contact, "friction", spec.friction, spec.friction >= 0.0, "must be >= 0");
  spec.length_scale = contact.optionalNumber("length_scale");
  if (spec.length_scale) {
    requireRange(contact, "length_scale", *spec.length_scale, *spec.length_scale > 0.0,
                 "must be > 0");
  }
  return spec;
}

TimeSpec readTime(const TableView& root) {
  const TableView time = root.requiredTable("time", {"steps", "end"});
  TimeSpec spec;
  spec.steps = time.requiredInt("steps");
  requireRange(time, "steps", spec.steps, spec.steps >= 2, "must be >= 2");
  spec.end = time.optionalNumber("end").value_or(spec.end);
  requireRange(time, "end", spec.end, spec.end > 0.0, "must be > 0");
  return spec;
}

/// `times` strictly increasing (one entry = a constant), `values` of the same length.
History readHistory(const TableView& entry) {
  History history{entry.requiredNumbers("times"), entry.requiredNumbers("values")};
  const ErrorReporter& errors = entry.errors();
  const std::string times = entry.keyPath("times");
  if (history.times.empty()) errors.fail(times, "key '" + times + "' must not be empty");
  for (std::size_t i = 1; i < history.times.size(); ++i) {
    if (!(history.times[i] > history.times[i - 1])) {
      errors.fail(times, "key '" + times + "' must be strictly increasing, but entry " +
                             std::to_string(i) + " = " + formatNumber(history.times[i]) +
                             " follows " + formatNumber(history.times[i - 1]));
    }
  }
  if (history.values.size() != history.times.size()) {
    const std::string values = entry.keyPath("values");
    errors.fail(values, "key '" + values + "' has " + std::to_string(history.values.size()) +
                            " entries but '" + times + "' has " +
                            std::to_string(history.times.size()) + ": they must match");
  }
  return history;
}

/// [[dirichlet]] and [[load]]: an array of tables {boundary, component, times, values}.
template <class Spec>
std::vector<Spec> readHistories(const TableView& root, std::string_view key, int dimension) {
  std::vector<Spec> specs;
  const toml::node* node = root.find(key);
  if (node == nullptr) return specs;
  const std::string path = root.keyPath(key);
  const auto* array = node->as_array();
  if (array == nullptr) {
    root.errors().wrongType(path, "an array of tables ([[" + path + "]])", *node);
  }
  for (std::size_t i = 0; i < array->size(); ++i) {
    const std::string entryPath = detail::indexPath(path, i);
    const TableView entry(detail::asTable(*array->get(i), entryPath, root.errors()), entryPath,
                          root.errors(), {"boundary", "component", "times", "values"});
    Spec spec;
    spec.boundary = requiredName(entry, "boundary");
    spec.component = readComponent(entry, dimension);
    spec.history = readHistory(entry);
    specs.push_back(std::move(spec));
  }
  return specs;
}

/// Reads a non-negative (or >= minimum) integer key of [solver] into `value`.
void readCount(const TableView& table, std::string_view key, int minimum, int& value) {
  value = table.optionalInt(key).value_or(value);
  requireRange(table, key, value, value >= minimum, minimum == 0 ? "must be >= 0" : "must be >= 1");
}

/// Keys of [solver] that have no effect since 0.2.0 (docs/changelog.md): still range-checked as in
/// 0.1.0, so that a scene 0.1.0 accepted is accepted, with a warning each.
void readDeprecated(const TableView& solver, std::vector<std::string>& warnings) {
  int modes_per_cycle = 1;
  readCount(solver, "pgd_modes_per_cycle", 1, modes_per_cycle);
  const double share = solver.optionalNumber("pgd_seed_share").value_or(0.0);
  requireRange(solver, "pgd_seed_share", share, share >= 0.0 && share <= 1.0, "must be in [0, 1]");
  for (const char* key : {"pgd_modes_per_cycle", "pgd_seed_share"})
    if (solver.has(key))
      warnings.push_back(std::string("key 'solver.") + key +
                         "' has no effect since version 0.2.0 and will be refused from 0.3.0 (docs/changelog.md)");
}

FasSpec readFas(const TableView& solver) {
  FasSpec fas;
  readCount(solver, "pre_relaxations", 1, fas.pre_relaxations);
  readCount(solver, "post_relaxations", 0, fas.post_relaxations);
  readCount(solver, "coarse_iterations", 1, fas.coarse_iterations);
  readCount(solver, "coarse_anderson", 0, fas.coarse_anderson);
  readCount(solver, "residual_vectors", 0, fas.residual_vectors);
  readCount(solver, "svd_modes", 0, fas.svd_modes);
  readCount(solver, "pgd_max_modes", 0, fas.pgd_max_modes);
  readCount(solver, "pgd_increment_modes", 0, fas.pgd_increment_modes);
  fas.pgd_anticipate = solver.optionalBool("pgd_anticipate").value_or(fas.pgd_anticipate);
  fas.pgd_gap_share = solver.optionalNumber("pgd_gap_share").value_or(fas.pgd_gap_share);
  requireRange(solver, "pgd_gap_share", fas.pgd_gap_share, fas.pgd_gap_share > 0.0 && fas.pgd_gap_share < 1.0,
               "must be in (0, 1)");
  fas.safeguard_growth = solver.optionalNumber("safeguard_growth");
  if (fas.safeguard_growth)
    requireRange(solver, "safeguard_growth", *fas.safeguard_growth,
                 *fas.safeguard_growth >= 1.0 && std::isfinite(*fas.safeguard_growth), "must be >= 1");
  fas.coarse_zone = solver.optionalBool("coarse_zone").value_or(fas.coarse_zone);
  fas.reduce_interface = solver.optionalBool("reduce_interface").value_or(fas.reduce_interface);
  fas.nested_instants = solver.optionalInt("nested_instants").value_or(fas.nested_instants);
  requireRange(solver, "nested_instants", fas.nested_instants, fas.nested_instants == 0 || fas.nested_instants >= 2,
               "must be 0 (off) or >= 2");
  fas.adapt_coarse_iterations =
      solver.optionalBool("adapt_coarse_iterations").value_or(fas.adapt_coarse_iterations);
  if (solver.has("coarse_start"))
    fas.coarse_start = readKeyword(solver, "coarse_start", {"zero", "mismatch"}) == "mismatch"
                           ? CoarseStart::InterfaceMismatch
                           : CoarseStart::ZeroCorrection;
  return fas;
}

SolverSpec readSolver(const TableView& root, std::vector<std::string>& warnings) {
  SolverSpec spec;
  const auto solver = root.optionalTable(
      "solver", {"name", "tolerance", "max_iterations", "search_scale", "relaxation", "pre_relaxations",
                 "post_relaxations", "coarse_iterations", "coarse_anderson", "coarse_zone", "reduce_interface",
                 "nested_instants", "adapt_coarse_iterations",
                 "safeguard_growth", "residual_vectors", "svd_modes", "coarse_start", "pgd_max_modes",
                 "pgd_increment_modes", "pgd_anticipate", "pgd_gap_share", "pgd_modes_per_cycle", "pgd_seed_share"});
  if (!solver) return spec;
  if (solver->has("name")) {
    spec.name = readKeyword(*solver, "name", kSolverNames);
  }
  spec.tolerance = solver->optionalNumber("tolerance").value_or(spec.tolerance);
  requireRange(*solver, "tolerance", spec.tolerance, spec.tolerance > 0.0, "must be > 0");
  spec.max_iterations = solver->optionalInt("max_iterations").value_or(spec.max_iterations);
  requireRange(*solver, "max_iterations", spec.max_iterations, spec.max_iterations >= 1,
               "must be >= 1");
  spec.search_scale = solver->optionalNumber("search_scale").value_or(spec.search_scale);
  requireRange(*solver, "search_scale", spec.search_scale, spec.search_scale > 0.0, "must be > 0");
  spec.relaxation = solver->optionalNumber("relaxation").value_or(spec.relaxation);
  requireRange(*solver, "relaxation", spec.relaxation,
               spec.relaxation > 0.0 && spec.relaxation <= 1.0, "must be in (0, 1]");
  spec.fas = readFas(*solver);
  readDeprecated(*solver, warnings);
  return spec;
}

OutputSpec readOutput(const TableView& root) {
  OutputSpec spec;
  const auto output = root.optionalTable("output", {"vtu", "vtu_stride"});
  if (!output) return spec;
  spec.vtu = output->optionalBool("vtu").value_or(spec.vtu);
  spec.vtu_stride = output->optionalInt("vtu_stride").value_or(spec.vtu_stride);
  requireRange(*output, "vtu_stride", spec.vtu_stride, spec.vtu_stride >= 1, "must be >= 1");
  return spec;
}

/// The table as JSON (toml++'s formatter; every number is finite once validated).
std::string toJson(const toml::table& table) {
  std::ostringstream json;
  json << toml::json_formatter{table};
  return json.str();
}

Scene readTable(const toml::table& table, const std::filesystem::path& source,
                const ErrorReporter& errors) {
  const TableView root(table, "", errors,
                       {"name", "dimension", "model", "mesh", "material", "obstacle", "contact", "time",
                        "dirichlet", "load", "solver", "output"});
  Scene scene;
  scene.source = source;
  scene.name = readName(root);
  scene.dimension = readDimension(root);
  scene.plane = readModel(root, scene.dimension);
  scene.mesh = readMesh(root, source, scene.dimension);
  scene.material = readMaterial(root);
  scene.obstacle = readObstacle(root, scene.dimension);
  scene.contact = readContact(root);
  scene.time = readTime(root);
  scene.dirichlet = readHistories<DirichletSpec>(root, "dirichlet", scene.dimension);
  scene.loads = readHistories<LoadSpec>(root, "load", scene.dimension);
  scene.solver = readSolver(root, scene.warnings);
  scene.output = readOutput(root);
  scene.parameters_json = toJson(table);
  return scene;
}

}  // namespace

Scene parseScene(const std::string& text, const std::filesystem::path& source,
                 const std::vector<std::string>& overrides) {
  ErrorReporter errors(source.string());
  toml::table table = detail::parseGuarded(text, errors);
  detail::applyOverrides(table, overrides, errors);
  return readTable(table, source, errors);
}

Scene readScene(const std::filesystem::path& file, const std::vector<std::string>& overrides) {
  const ErrorReporter errors(file.string());
  std::error_code ec;
  if (std::filesystem::is_directory(file, ec)) errors.failFile("is a folder, not a scene file");
  std::ifstream in(file, std::ios::binary);
  if (!in) errors.failFile("cannot open the scene file (missing or unreadable)");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) errors.failFile("cannot read the scene file");
  return parseScene(text.str(), file, overrides);
}

}  // namespace stc
