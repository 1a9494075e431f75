#include "stcontact/scene/scene_reader.hpp"

#include <toml++/toml.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <initializer_list>
#include <span>
#include <sstream>
#include <type_traits>
#include <utility>

#include "stcontact/core/input_error.hpp"
#include "stcontact/core/missing_file_error.hpp"
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

std::string readKeyword(const TableView& table, std::string_view key, const std::vector<std::string_view>& allowed) {
  return readKeyword(table, key, std::span<const std::string_view>(allowed.data(), allowed.size()));
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
    // Three entries in a scene that says no dimension: most likely a 3D scene without `dimension = 3`.
    const std::string hint = dimension == 2 && x.size() == 3 ? " (a 3D scene needs 'dimension = 3' at its top)" : "";
    table.errors().fail(path, "key '" + path + "' must have " + std::to_string(dimension) + " entries " +
                                  (dimension == 3 ? "[x, y, z]" : "[x, y]") + ", got " + std::to_string(x.size()) + hint);
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
// The name's characters as the message shows them: control characters (a NUL cut the message and
// the folder name) as \xNN.
std::string printable(const std::string& text) {
  std::string out;
  for (const unsigned char c : text) {
    if (c >= 0x20 && c != 0x7f) {
      out += static_cast<char>(c);
      continue;
    }
    char code[8];
    std::snprintf(code, sizeof code, "\\x%02x", c);
    out += code;
  }
  return out;
}

// The name names the default output folder (results/<name>/...): a plain file name without
// control characters, refused before anything is created.
std::string readName(const TableView& root) {
  std::string name = requiredName(root, "name");
  const bool control = std::any_of(name.begin(), name.end(), [](unsigned char c) { return c < 0x20 || c == 0x7f; });
  if (name.find_first_of("/\\") != std::string::npos || name == "." || name == ".." || control) {
    root.errors().fail("name", "key 'name' = \"" + printable(name) +
                                   "\" must be a plain file name (no '/', '\\', control character, '.' or '..')");
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
      "mesh", {"generator", "file", "radius", "arc_nodes", "grading", "divisions", "core", "thickness", "layers",
               "mirror_gap"});
  const ErrorReporter& errors = mesh.errors();
  const bool hasGenerator = mesh.has("generator");
  if (hasGenerator == mesh.has("file")) {
    errors.fail("mesh", hasGenerator
                            ? "keys 'mesh.generator' and 'mesh.file' exclude each other: give one"
                            : "missing required key 'mesh.generator' or 'mesh.file' (give one)");
  }
  MeshSpec spec;
  spec.mirror_gap = mesh.optionalNumber("mirror_gap");
  if (spec.mirror_gap)
    requireRange(mesh, "mirror_gap", *spec.mirror_gap, *spec.mirror_gap >= 0.0 && std::isfinite(*spec.mirror_gap),
                 "must be >= 0");
  if (hasGenerator) {
    const std::optional<std::string> named = mesh.optionalString("generator");
    if (dimension == 2 && named && (*named == "half_ball" || *named == "half_disc_slab"))
      errors.fail(mesh.keyPath("generator"), "key '" + mesh.keyPath("generator") + "' = \"" + *named +
                                                 "\" makes a 3D body: a 3D scene needs 'dimension = 3' at its top");
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

MaterialSpec readMaterial(const TableView& material) {
  MaterialSpec spec;
  spec.young = material.requiredNumber("young");
  requireRange(material, "young", spec.young, spec.young > 0.0, "must be > 0");
  spec.poisson = material.requiredNumber("poisson");
  // kPoissonLow, kPoissonHigh (model_spec.hpp: where double precision resolves the stiffness).
  requireRange(material, "poisson", spec.poisson, spec.poisson >= kPoissonLow && spec.poisson <= kPoissonHigh,
               "must be in [-0.999999, 0.4999995] (1 + ν and 1 - 2ν at least 1e-6)");
  return spec;
}

/// Fails with "key 'P' <why>" when `table` has `key`.
void refuseKey(const TableView& table, std::string_view key, const std::string& why) {
  if (!table.has(key)) return;
  const std::string path = table.keyPath(key);
  table.errors().fail(path, "key '" + path + "' " + why);
}

// `dimension` entries of a nonzero finite vector, normalised (a normal: obstacle.normal, contact.normal).
Eigen::VectorXd readUnitVector(const TableView& table, std::string_view key, int dimension) {
  const Eigen::VectorXd v = readVector(table, key, dimension);
  const double length = v.norm();
  if (!(length > 0.0) || !std::isfinite(length)) {
    std::string entries;
    for (double x : v) entries += (entries.empty() ? "" : ", ") + formatNumber(x);
    const std::string path = table.keyPath(key);
    table.errors().fail(path, "key '" + path + "' = [" + entries + "] must be a nonzero finite vector");
  }
  return v / length;
}

// A plane through `point` with the unit `normal` pointing into the body.
void readPlane(const TableView& obstacle, int dimension, ObstacleSpec& spec) {
  spec.point = readVector(obstacle, "point", dimension);
  spec.normal = readUnitVector(obstacle, "normal", dimension);
}

// A sphere (3D) or cylinder (2D): `centre`, `radius` > 0 and `side`, "outside" (the default: the
// obstacle is the ball) or "inside" (the body lies in the ball: a seat).
void readBall(const TableView& obstacle, int dimension, ObstacleSpec& spec) {
  spec.centre = readVector(obstacle, "centre", dimension);
  spec.radius = obstacle.requiredNumber("radius");
  requireRange(obstacle, "radius", spec.radius, spec.radius > 0.0 && std::isfinite(spec.radius), "must be > 0");
  if (obstacle.has("side")) spec.inside = readKeyword(obstacle, "side", {"outside", "inside"}) == "inside";
}

// The keys of each type; a key of another type is refused with the type's list.
void requireKeysOfType(const TableView& obstacle, const std::string& type, std::initializer_list<const char*> keys) {
  std::string list;
  for (const char* k : keys) list += (list.empty() ? "'" : ", '") + std::string(k) + "'";
  for (const char* key : {"point", "normal", "centre", "radius", "side", "points", "file"}) {
    const auto own = [&](const char* k) { return std::string(k) == key; };
    if (std::find_if(keys.begin(), keys.end(), own) == keys.end())
      refuseKey(obstacle, key, "does not apply to obstacle.type = \"" + type + "\" (its keys: " + list + ")");
  }
}

template <class Spec>
std::vector<Spec> readHistories(const TableView& root, std::string_view key, int dimension, const TimeSpec& time);

// A polyline (2D): `points` = [x0, y0, x1, y1, ...], at least two points, consecutive ones distinct.
void readPolyline(const TableView& obstacle, ObstacleSpec& spec) {
  const std::vector<double> xy = obstacle.requiredNumbers("points");
  const std::string path = obstacle.keyPath("points");
  if (xy.size() < 4 || xy.size() % 2 != 0)
    obstacle.errors().fail(path, "key '" + path + "' must list x, y pairs of at least two points [x0, y0, x1, y1, ...], got " +
                                     std::to_string(xy.size()) + " numbers");
  spec.points = Eigen::Map<const Eigen::Matrix2Xd>(xy.data(), 2, static_cast<Eigen::Index>(xy.size() / 2));
  for (Eigen::Index i = 1; i < spec.points.cols(); ++i)
    if (spec.points.col(i) == spec.points.col(i - 1))
      obstacle.errors().fail(path, "key '" + path + "': points " + std::to_string(i - 1) + " and " + std::to_string(i) +
                                       " coincide (a segment must have a length)");
  spec.type = ObstacleType::Polyline;
}

// A triangulated surface (3D): `file`, a Gmsh surface mesh resolved against the scene's folder (read
// when the problem is built), and `side`.
void readSurface(const TableView& obstacle, const std::filesystem::path& source, ObstacleSpec& spec) {
  const std::filesystem::path file = requiredName(obstacle, "file");
  spec.file = file.is_absolute() ? file : (source.parent_path() / file).lexically_normal();
  if (obstacle.has("side")) spec.inside = readKeyword(obstacle, "side", {"outside", "inside"}) == "inside";
  spec.type = ObstacleType::Surface;
}

ObstacleSpec readObstacle(const TableView& root, const std::filesystem::path& source, int dimension, const TimeSpec& time) {
  const TableView obstacle =
      root.requiredTable("obstacle", {"type", "point", "normal", "centre", "radius", "side", "points", "file", "motion"});
  ObstacleSpec spec;
  spec.motion = readHistories<ObstacleMotionSpec>(obstacle, "motion", dimension, time);
  const std::string type =
      obstacle.has("type") ? readKeyword(obstacle, "type", {"plane", "sphere", "cylinder", "polyline", "surface"}) : "plane";
  if (type == "plane") {
    requireKeysOfType(obstacle, type, {"point", "normal"});
    readPlane(obstacle, dimension, spec);
    return spec;
  }
  if (type == "polyline") {
    if (dimension != 2)
      obstacle.errors().fail(obstacle.keyPath("type"), "key '" + obstacle.keyPath("type") +
                                                           "' = \"polyline\" needs a 2D scene (in 3D: \"surface\", a "
                                                           "Gmsh surface mesh)");
    requireKeysOfType(obstacle, type, {"points"});
    readPolyline(obstacle, spec);
    return spec;
  }
  if (type == "surface") {
    if (dimension != 3)
      obstacle.errors().fail(obstacle.keyPath("type"), "key '" + obstacle.keyPath("type") +
                                                           "' = \"surface\" needs a 3D scene (in 2D: \"polyline\")");
    requireKeysOfType(obstacle, type, {"file", "side"});
    readSurface(obstacle, source, spec);
    return spec;
  }
  const bool sphere = type == "sphere";
  if (sphere != (dimension == 3)) {
    const std::string path = obstacle.keyPath("type");
    obstacle.errors().fail(path, "key '" + path + "' = \"" + type + "\" needs a " + (sphere ? "3D" : "2D") +
                                     " scene (a " + (sphere ? "cylinder" : "sphere") + " in " +
                                     (sphere ? "2D" : "3D") + ")");
  }
  requireKeysOfType(obstacle, type, {"centre", "radius", "side"});
  spec.type = sphere ? ObstacleType::Sphere : ObstacleType::Cylinder;
  readBall(obstacle, dimension, spec);
  return spec;
}

ContactSpec readContact(const TableView& root, int dimension) {
  const TableView contact =
      root.requiredTable("contact", {"boundary", "master", "normal", "pairing", "friction", "length_scale"});
  ContactSpec spec;
  spec.boundary = requiredName(contact, "boundary");
  if (contact.has("master")) spec.master = requiredName(contact, "master");
  if (spec.master == spec.boundary)
    contact.errors().fail(contact.keyPath("master"), "key '" + contact.keyPath("master") +
                                                         "' must name another boundary than 'contact.boundary'");
  if (!spec.master.empty() && contact.has("normal")) spec.normal = readUnitVector(contact, "normal", dimension);
  if (spec.master.empty()) refuseKey(contact, "normal", "applies to two bodies only (with 'contact.master')");
  if (spec.master.empty()) refuseKey(contact, "pairing", "applies to two bodies only (with 'contact.master')");
  if (contact.has("pairing")) spec.to_segment = readKeyword(contact, "pairing", {"node", "segment"}) == "segment";
  if (spec.to_segment && spec.normal.size() == 0)
    contact.errors().fail(contact.keyPath("pairing"), "key '" + contact.keyPath("pairing") +
                                                          "' = \"segment\" needs 'contact.normal' (the line along which a slave node meets a master facet)");
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

/// A [[load]] entry's `type` ("force", the default; "pressure"; "body") and the keys it takes: a
/// force its boundary and component, a pressure its boundary (along the inward normal), a body force
/// its component (on the whole body).
void readLoadKind(const TableView& entry, int dimension, LoadSpec& spec) {
  const std::string type = entry.has("type") ? readKeyword(entry, "type", {"force", "pressure", "body"}) : "force";
  spec.kind = type == "pressure" ? LoadKind::Pressure : type == "body" ? LoadKind::Body : LoadKind::Force;
  if (spec.kind == LoadKind::Body) refuseKey(entry, "boundary", "does not apply to type = \"body\" (on the whole body)");
  else spec.boundary = requiredName(entry, "boundary");
  if (spec.kind == LoadKind::Pressure)
    refuseKey(entry, "component", "does not apply to type = \"pressure\" (along the inward normal)");
  else spec.component = readComponent(entry, dimension);
}

/// With `period` and `cycles` (both or neither), `one` holds one period from its first time and is
/// repeated `cycles` times: point i of cycle j at t_i + j·period; after the last cycle its last value
/// holds, as after any history. The period is a whole number of time steps, so that every cycle meets
/// the same instants; the points lie within one period and end on the value they start with.
History periodicHistory(const TableView& entry, History one, const TimeSpec& time) {
  const bool has_period = entry.has("period"), has_cycles = entry.has("cycles");
  if (!has_period && !has_cycles) return one;
  const ErrorReporter& errors = entry.errors();
  const char* given = has_period ? "period" : "cycles";
  const char* missing = has_period ? "cycles" : "period";
  if (!has_period || !has_cycles)
    errors.fail(entry.keyPath(given), "key '" + entry.keyPath(given) + "' needs '" + entry.keyPath(missing) +
                                          "' too (a periodic history takes both)");
  const double period = entry.requiredNumber("period");
  requireRange(entry, "period", period, period > 0.0 && std::isfinite(period), "must be > 0");
  const int cycles = entry.requiredInt("cycles");
  requireRange(entry, "cycles", cycles, cycles >= 1, "must be >= 1");
  const double dt = time.end / (time.steps - 1), steps = period / dt;
  if (std::abs(steps - std::round(steps)) > 1e-9 * std::max(1.0, steps))
    errors.fail(entry.keyPath("period"), "key '" + entry.keyPath("period") + "' = " + formatNumber(period) +
                                             " is not a whole number of time steps (time.end / (time.steps - 1) = " +
                                             formatNumber(dt) + "): every cycle must meet the same instants");
  const double span = one.times.back() - one.times.front();
  if (span > period * (1.0 + 1e-12))
    errors.fail(entry.keyPath("times"), "key '" + entry.keyPath("times") + "' spans " + formatNumber(span) +
                                            ", more than one period (" + formatNumber(period) + ")");
  if (one.values.front() != one.values.back())
    errors.fail(entry.keyPath("values"), "key '" + entry.keyPath("values") + "' must end on the value it starts with (" +
                                             formatNumber(one.values.front()) + ", not " +
                                             formatNumber(one.values.back()) + ") to repeat");
  const bool whole_period = std::abs(span - period) <= 1e-12 * period;
  // Only the cycles that begin within the time grid are written out: the grid samples nothing of the
  // others (after the last cycle its last value, the first, holds), and `cycles` may be any count
  // (2e9 held 2e9 copies of the period in memory before any size was checked).
  const double begins = std::floor((time.end - one.times.front()) / period) + 1.0;
  const int written = static_cast<int>(std::clamp(begins, 1.0, static_cast<double>(cycles)));
  History all;
  for (int j = 0; j < written; ++j)
    for (std::size_t i = (j > 0 && whole_period) ? 1 : 0; i < one.times.size(); ++i) {
      all.times.push_back(one.times[i] + j * period);
      all.values.push_back(one.values[i]);
    }
  return all;
}

/// [[dirichlet]] and [[load]]: an array of tables {boundary, component, times, values[, period,
/// cycles]}.
template <class Spec>
std::vector<Spec> readHistories(const TableView& root, std::string_view key, int dimension, const TimeSpec& time) {
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
                          root.errors(), {"type", "boundary", "component", "times", "values", "period", "cycles"});
    Spec spec;
    if constexpr (std::is_same_v<Spec, LoadSpec>) readLoadKind(entry, dimension, spec);
    else {
      refuseKey(entry, "type", "applies to [[load]] entries only");
      if constexpr (std::is_same_v<Spec, ObstacleMotionSpec>)
        refuseKey(entry, "boundary", "does not apply to the obstacle's motion (it moves as a whole)");
      else spec.boundary = requiredName(entry, "boundary");
      spec.component = readComponent(entry, dimension);
    }
    spec.history = periodicHistory(entry, readHistory(entry), time);
    specs.push_back(std::move(spec));
  }
  return specs;
}

/// Keys of [solver] without effect since 0.2.0, refused from 0.3.0 (docs/changelog.md).
constexpr std::array<std::string_view, 2> kRemovedSolverKeys = {"pgd_modes_per_cycle", "pgd_seed_share"};

void refuseRemoved(const TableView& solver) {
  for (const std::string_view key : kRemovedSolverKeys)
    if (solver.has(key)) {
      const std::string path = solver.keyPath(key);
      solver.errors().fail(path, "key '" + path + "' was removed in version 0.3.0 (it had no effect since 0.2.0; "
                                 "docs/changelog.md): delete it");
    }
}

/// The scene keys of an options struct's fields (src/options/option_fields.hpp), each once, in order.
class SceneKeys {
 public:
  template <class T, class Rule>
  void operator()(const char* key, const T&, const Rule&, Exposure exposure = Exposure::SceneKey) {
    if (exposure == Exposure::SceneKey && std::find(keys_.begin(), keys_.end(), key) == keys_.end())
      keys_.emplace_back(key);
  }
  std::vector<std::string_view> keys() const { return keys_; }

 private:
  std::vector<std::string_view> keys_;
};

/// Reads each field's scene key, when present, into the field and checks it against the field's range
/// (the same range validate() checks, worded the same).
class SceneFieldReader {
 public:
  explicit SceneFieldReader(const TableView& table) : table_(table) {}

  void operator()(const char* key, int& value, const Range& range, Exposure exposure = Exposure::SceneKey) const {
    if (!present(key, exposure)) return;
    value = *table_.optionalInt(key);
    requireRange(table_, key, value, range.holds(value), range.rule);
  }
  void operator()(const char* key, double& value, const Range& range, Exposure exposure = Exposure::SceneKey) const {
    if (!present(key, exposure)) return;
    value = *table_.optionalNumber(key);
    requireRange(table_, key, value, range.holds(value), range.rule);
  }
  template <class T>
  void operator()(const char* key, std::optional<T>& value, const Range& range,
                  Exposure exposure = Exposure::SceneKey) const {
    if (!present(key, exposure)) return;
    T read{};
    (*this)(key, read, range, exposure);
    value = read;
  }
  void operator()(const char* key, bool& value, const Range&, Exposure exposure = Exposure::SceneKey) const {
    if (present(key, exposure)) value = *table_.optionalBool(key);
  }
  template <class E>
  void operator()(const char* key, E& value, Keywords<E> names, Exposure exposure = Exposure::SceneKey) const {
    if (!present(key, exposure)) return;
    std::vector<std::string_view> allowed;
    for (const auto& [name, v] : names) allowed.push_back(name);
    const std::string text = readKeyword(table_, key, allowed);
    for (const auto& [name, v] : names)
      if (name == text) value = v;
  }

 private:
  bool present(const char* key, Exposure exposure) const { return exposure == Exposure::SceneKey && table_.has(key); }
  const TableView& table_;
};

/// [solver] into scene.solver and scene.search_direction (solverTableFields: the search direction
/// belongs to the model, the rest to the strategies).
void readSolver(const TableView& root, Scene& scene) {
  SceneKeys keys;
  keys("name", scene.solver.strategy, Keywords<Strategy>(kStrategies));
  solverTableFields(scene, keys);
  std::vector<std::string_view> allowed = keys.keys();
  allowed.insert(allowed.end(), kRemovedSolverKeys.begin(), kRemovedSolverKeys.end());
  const auto solver = root.optionalTable("solver", allowed);
  if (!solver) return;
  refuseRemoved(*solver);
  const SceneFieldReader read(*solver);
  read("name", scene.solver.strategy, Keywords<Strategy>(kStrategies));
  solverTableFields(scene, read);
}

OutputSpec readOutput(const TableView& root) {
  OutputSpec spec;
  SceneKeys keys;
  OutputSpec::fields(spec, keys);
  const auto output = root.optionalTable("output", keys.keys());
  if (!output) return spec;
  OutputSpec::fields(spec, SceneFieldReader(*output));
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
                       {"name", "dimension", "model", "mesh", "material", "master_material", "obstacle", "contact", "time",
                        "dirichlet", "load", "solver", "output"});
  Scene scene;
  scene.source = source;
  scene.name = readName(root);
  scene.dimension = readDimension(root);
  scene.plane = readModel(root, scene.dimension);
  scene.mesh = readMesh(root, source, scene.dimension);
  scene.material = readMaterial(root.requiredTable("material", {"young", "poisson"}));
  scene.contact = readContact(root, scene.dimension);
  scene.time = readTime(root);
  if (scene.contact.master.empty()) scene.obstacle = readObstacle(root, source, scene.dimension, scene.time);
  if (const auto master = root.optionalTable("master_material", {"young", "poisson"})) {
    if (scene.contact.master.empty())
      errors.fail("master_material", "table [master_material] applies to two bodies only (with 'contact.master')");
    scene.master_material = readMaterial(*master);
  }
  if (!scene.contact.master.empty() && root.has("obstacle"))
    errors.fail("obstacle", "table [obstacle] and key 'contact.master' exclude each other: a rigid obstacle, or a "
                            "second body's boundary to touch");
  scene.dirichlet = readHistories<DirichletSpec>(root, "dirichlet", scene.dimension, scene.time);
  scene.loads = readHistories<LoadSpec>(root, "load", scene.dimension, scene.time);
  readSolver(root, scene);
  scene.output = readOutput(root);
  scene.parameters_json = toJson(table);
  toml::table model = table;
  model.erase("solver");
  model.erase("output");
  scene.model_json = toJson(model);
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
  // A device (/dev/zero, /dev/urandom) or a pipe would be read without end into memory.
  if (std::filesystem::exists(file, ec) && !std::filesystem::is_regular_file(file, ec))
    errors.failFile("is not a regular file (a device, a pipe or a socket): give a scene file");
  if (std::filesystem::exists(file, ec) && std::filesystem::file_size(file, ec) > kMaxSceneBytes)
    errors.failFile("holds " + std::to_string(std::filesystem::file_size(file, ec)) +
                    " bytes: a scene is a few kB of TOML (give a large mesh as mesh.file)");
  std::ifstream in(file, std::ios::binary);
  if (!in) {
    const std::string message = "cannot open the scene file (missing or unreadable)";
    if (MissingFileError::isMissing(file)) errors.failMissingFile(message);
    errors.failFile(message);
  }
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) errors.failFile("cannot read the scene file");
  return parseScene(text.str(), file, overrides);
}

}  // namespace stc
