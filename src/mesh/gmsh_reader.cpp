#include "stcontact/mesh/gmsh_reader.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <set>
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

#include "stcontact/core/input_error.hpp"
#include "stcontact/core/missing_file_error.hpp"
#include "stcontact/mesh/detail/gmsh_sections.hpp"

namespace stc::detail {
namespace {

/// Views into the reader's current line: valid only until the next line is read.
using Tokens = std::vector<std::string_view>;

Tokens split(std::string_view line) {
  Tokens out;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    std::size_t j = i;
    while (j < line.size() && line[j] != ' ' && line[j] != '\t') ++j;
    if (j > i) out.push_back(line.substr(i, j - i));
    i = j;
  }
  return out;
}

/// The start of a line, for quoting in messages.
std::string quote(std::string_view text) {
  constexpr std::size_t kMax = 40;
  std::string out = "'";  // appended step by step: GCC 12 warns (-Wrestrict, falsely) on a + chain here
  // A binary file's bytes would reach the terminal as they are: each byte outside printable ASCII
  // is shown as \xNN.
  for (const unsigned char c : text.substr(0, kMax)) {
    if (c >= 0x20 && c < 0x7f) {
      out.push_back(static_cast<char>(c));
      continue;
    }
    char code[8];
    std::snprintf(code, sizeof code, "\\x%02x", c);
    out.append(code);
  }
  out.append(text.size() > kMax ? "...'" : "'");
  return out;
}

/// Line-by-line access that knows the line number and the section being read, so that every
/// error can name the file, the line and what was expected.
class LineReader {
 public:
  LineReader(std::istream& in, std::string source) : in_(in), source_(std::move(source)) {}

  /// Advances to the next non-blank line (trailing blanks and '\r' removed); false at the end.
  bool next() {
    while (std::getline(in_, line_)) {
      ++number_;
      line_.erase(line_.find_last_not_of(" \t\r") + 1);  // npos + 1 == 0 clears a blank line
      if (!line_.empty()) return true;
    }
    return false;
  }
  void enterSection(const std::string& header) { end_ = "$End" + header.substr(1); }
  /// Advances to the next data line of the current section.
  void nextData(const std::string& expected) {
    if (!next()) failFile("truncated file (expected " + end_ + ")");
    if (line_[0] == '$')
      fail("found " + quote(line_) + " where " + expected + " was expected (the section holds " +
           "fewer entries than its header announces)");
  }
  /// Reads the line that must close the current section.
  void expectEnd() {
    if (!next()) failFile("truncated file (expected " + end_ + ")");
    if (line_ != end_) fail("expected " + end_ + ", found " + quote(line_));
  }
  /// The current line, which must hold exactly `count` tokens.
  Tokens tokens(std::size_t count, const std::string& what) const {
    Tokens t = split(line_);
    if (t.size() != count)
      fail("expected " + std::to_string(count) + " numbers " + what + ", found " +
           std::to_string(t.size()));
    return t;
  }
  long long integer(std::string_view token, const std::string& what) const {
    long long value = 0;
    const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
    if (ec != std::errc() || end != token.data() + token.size())
      fail("expected an integer for " + what + ", found " + quote(token));
    return value;
  }
  long long count(std::string_view token, const std::string& what) const {
    const long long value = integer(token, what);
    if (value < 0) fail(what + " is negative (" + std::to_string(value) + ")");
    return value;
  }
  double real(std::string_view token, const std::string& what) const {
    double value = 0.0;
    const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
    if (ec != std::errc() || end != token.data() + token.size() || !std::isfinite(value))
      fail("expected a finite number for " + what + ", found " + quote(token));
    return value;
  }
  const std::string& line() const { return line_; }
  int lineNumber() const { return number_; }
  [[noreturn]] void fail(const std::string& what) const {
    throw InputError(source_ + ": line " + std::to_string(number_) + ": " + what);
  }
  [[noreturn]] void failFile(const std::string& what) const {
    throw InputError(source_ + ": " + what);
  }

 private:
  std::istream& in_;
  std::string source_;
  std::string line_;
  int number_ = 0;
  std::string end_;
};

void readMeshFormat(LineReader& r) {
  r.enterSection("$MeshFormat");
  r.nextData("the version line");
  const Tokens t = split(r.line());
  if (t.size() != 3) r.fail("expected 'version file-type data-size', found " + quote(r.line()));
  const std::string version(t[0]);
  const bool ascii = t[1] == "0";
  if (version != "4.1" || !ascii)
    r.failFile("unsupported mesh format: version " + version + (ascii ? " ASCII" : " binary") +
               " (only MSH 4.1 ASCII is read; in Gmsh set Mesh.MshFileVersion = 4.1 and " +
               "Mesh.Binary = 0)");
  r.expectEnd();
}

void readPhysicalNames(LineReader& r, GmshData& data) {
  r.nextData("the number of names");
  const long long n = r.count(r.tokens(1, "(the number of names)")[0], "the number of names");
  for (long long i = 0; i < n; ++i) {
    r.nextData("a physical name");
    const Tokens t = split(r.line());
    const std::size_t open = r.line().find('"');
    const std::size_t close = r.line().rfind('"');
    if (t.size() < 3 || open == std::string::npos || close == open)
      r.fail("expected 'dimension tag \"name\"', found " + quote(r.line()));
    const long long dim = r.integer(t[0], "the dimension of a physical name");
    const long long tag = r.integer(t[1], "the tag of a physical name");
    data.names[{dim, tag}] = r.line().substr(open + 1, close - open - 1);
  }
  r.expectEnd();
}

/// One entity line of $Entities (MSH 4.1): points are "tag x y z nphys phys...", curves and
/// surfaces "tag minx miny minz maxx maxy maxz nphys phys... nbound bound...".
void readEntity(LineReader& r, int dim, GmshData& data) {
  static const char* kKinds[] = {"point", "curve", "surface", "volume"};
  const std::string what = std::string(kKinds[dim]) + " entity";
  r.nextData("a " + what);
  const Tokens t = split(r.line());
  std::size_t pos = 0;
  auto take = [&](const std::string& field) {
    if (pos >= t.size()) r.fail("incomplete " + what + " (missing " + field + ")");
    return t[pos++];
  };
  auto takeList = [&](const std::string& field) {  // "n a_1 ... a_n", n checked before use
    const long long n = r.count(take("the number of " + field), "the number of " + field);
    if (n > static_cast<long long>(t.size() - pos)) r.fail("incomplete " + what + " (" + field + ")");
    std::vector<long long> list(static_cast<std::size_t>(n));
    for (auto& item : list) item = r.integer(take(field), field);
    return list;
  };
  const long long tag = r.integer(take("its tag"), what + " tag");
  for (int i = 0; i < (dim == 0 ? 3 : 6); ++i) r.real(take("coordinates"), what + " coordinates");
  std::vector<long long> physicals = takeList("physical tags");
  if (dim > 0) takeList("bounding entities");
  if (pos != t.size()) r.fail("too many numbers for " + what + " " + std::to_string(tag));
  if (dim == 1) data.curve_groups[tag] = std::move(physicals);
  if (dim == 2) data.surface_groups[tag] = std::move(physicals);
}

void readEntities(LineReader& r, GmshData& data) {
  r.nextData("the entity counts");
  const Tokens t = r.tokens(4, "(numbers of points, curves, surfaces, volumes)");
  std::array<long long, 4> counts{};  // parsed now: `t` views the line that readEntity replaces
  for (int dim = 0; dim < 4; ++dim) counts[dim] = r.count(t[dim], "an entity count");
  for (int dim = 0; dim < 4; ++dim)
    for (long long i = 0; i < counts[dim]; ++i) readEntity(r, dim, data);
  r.expectEnd();
}

/// One block of $Nodes: its header, the node tags, then their coordinates.
long long readNodeBlock(LineReader& r, GmshData& data) {
  r.nextData("a node block header");
  const Tokens h = r.tokens(4, "(entityDim entityTag parametric numNodes) in a node block header");
  const long long dim = r.integer(h[0], "the entity dimension");
  const long long parametric = r.integer(h[2], "the parametric flag");
  const long long n = r.count(h[3], "the number of nodes in the block");
  if (dim < 0 || dim > 3 || (parametric != 0 && parametric != 1))
    r.fail("invalid node block header " + quote(r.line()));
  const std::size_t first = data.node_tags.size();
  for (long long i = 0; i < n; ++i) {
    r.nextData("a node tag");
    const long long tag = r.integer(r.tokens(1, "(a node tag)")[0], "a node tag");
    if (!data.node_index.emplace(tag, static_cast<int>(data.node_tags.size())).second)
      r.fail("node " + std::to_string(tag) + " is listed twice");
    data.node_tags.push_back(tag);
  }
  const std::size_t numbers = 3 + (parametric ? static_cast<std::size_t>(dim) : 0);
  for (long long i = 0; i < n; ++i) {
    const std::string node = "node " + std::to_string(data.node_tags[first + i]);
    r.nextData("the coordinates of " + node);
    const Tokens c = r.tokens(numbers, "(x y z" + std::string(parametric ? " u..." : "") +
                                           ") for " + node);
    const double x = r.real(c[0], "x of " + node);
    const double y = r.real(c[1], "y of " + node);
    const double z = r.real(c[2], "z of " + node);
    if (data.dimension == 2 && std::abs(z) > 1e-12 * std::max({1.0, std::abs(x), std::abs(y)}))
      r.fail("not a 2D mesh: " + node + " has z = " + std::string(c[2]) +
             " (all nodes must lie in the plane z = 0; a volume mesh needs dimension = 3 in the scene)");
    data.coords.emplace_back(x, y, z);
  }
  return n;
}

/// A $Nodes or $Elements section: "numEntityBlocks numX minXTag maxXTag", then the blocks, read
/// by `readBlock`, whose counts must add up to numX. `kind` is "node" or "element".
void readBlocks(LineReader& r, GmshData& data, const std::string& kind,
                long long (*readBlock)(LineReader&, GmshData&)) {
  const std::string Kind = static_cast<char>(std::toupper(kind[0])) + kind.substr(1);
  r.nextData("the " + kind + " counts");
  const Tokens h = r.tokens(4, "(numEntityBlocks num" + Kind + "s min" + Kind + "Tag max" + Kind + "Tag)");
  const long long blocks = r.count(h[0], "the number of " + kind + " blocks");
  const long long total = r.count(h[1], "the number of " + kind + "s");
  long long read = 0;
  for (long long b = 0; b < blocks; ++b) read += readBlock(r, data);
  if (read != total)
    r.fail("$" + Kind + "s announces " + std::to_string(total) + " " + kind + "s but its blocks hold " +
           std::to_string(read));
  r.expectEnd();
}

/// Gmsh element types by number (reference manual, "MSH file format"), for messages.
std::string elementTypeName(long long type) {
  static const std::map<long long, const char*> kNames = {
      {1, "2-node line"}, {2, "3-node triangle"}, {3, "4-node quadrangle"},
      {4, "4-node tetrahedron"}, {5, "8-node hexahedron"}, {6, "6-node prism"},
      {7, "5-node pyramid"}, {8, "3-node line"}, {9, "6-node triangle"}, {10, "9-node quadrangle"},
      {11, "10-node tetrahedron"}, {15, "1-node point"}, {16, "8-node quadrangle"},
      {21, "10-node triangle"}, {26, "4-node line"}};
  const auto it = kNames.find(type);
  return "element type " + std::to_string(type) + (it == kNames.end() ? "" : " (" +
         std::string(it->second) + ")");
}

/// Element types a reader of `dimension` takes: type -> (entity dimension, nodes per element).
/// 2D: triangles (the body), lines (boundaries), points; 3D: tetrahedra (the body), triangles
/// (boundaries), lines and points (skipped).
const std::map<long long, std::pair<long long, std::size_t>>& acceptedTypes(int dimension) {
  static const std::map<long long, std::pair<long long, std::size_t>> kPlane = {{1, {1, 2}}, {2, {2, 3}}, {15, {0, 1}}};
  static const std::map<long long, std::pair<long long, std::size_t>> kSolid = {
      {1, {1, 2}}, {2, {2, 3}}, {4, {3, 4}}, {15, {0, 1}}};
  return dimension == 3 ? kSolid : kPlane;
}

/// Keeps one element of a block (its nodes in file order) where the reader of data.dimension wants it.
void keepElement(GmshData& data, long long type, long long entity, long long tag, int line,
                 const std::array<int, 4>& nodes) {
  if (data.dimension == 2 && type == 2) {
    data.triangles.push_back({nodes[0], nodes[1], nodes[2]});
    data.triangle_origin.emplace_back(tag, line);
  } else if (data.dimension == 2 && type == 1) {
    data.curve_edges[entity].push_back({{nodes[0], nodes[1]}, tag, line});
  } else if (type == 4) {
    data.tets.push_back(nodes);
    data.tet_origin.emplace_back(tag, line);
  } else if (type == 2) {
    data.surface_triangles[entity].push_back({{nodes[0], nodes[1], nodes[2]}, tag, line});
  }
}

/// One block of $Elements: the body's elements and the boundaries' are kept, points (and lines in
/// 3D) skipped, anything else refused.
long long readElementBlock(LineReader& r, GmshData& data) {
  r.nextData("an element block header");
  const Tokens h = r.tokens(4, "(entityDim entityTag elementType numElements) in an element "
                               "block header");
  const long long dim = r.integer(h[0], "the entity dimension");
  const long long entity = r.integer(h[1], "the entity tag");
  const long long type = r.integer(h[2], "the element type");
  const long long n = r.count(h[3], "the number of elements in the block");
  const auto& kAccepted = acceptedTypes(data.dimension);
  const auto accepted = kAccepted.find(type);
  if (data.dimension == 2 && type == 4)
    r.fail(elementTypeName(type) + ": the file holds a volume mesh; set dimension = 3 in the scene");
  if (accepted == kAccepted.end())
    r.fail(elementTypeName(type) + " is not supported: the reader takes " +
           (data.dimension == 3 ? "4-node tetrahedra, 3-node triangles, " : "3-node triangles, ") +
           "2-node lines and points (set Mesh.ElementOrder = 1 and do not recombine)");
  const auto [expected_dim, per] = accepted->second;
  if (dim != expected_dim)
    r.fail(elementTypeName(type) + " in a block of dimension " + std::to_string(dim));
  for (long long i = 0; i < n; ++i) {
    r.nextData("an element");
    const Tokens t = r.tokens(1 + per, "(element tag, then " + std::to_string(per) +
                                           " node tag(s)) in a block of " + elementTypeName(type));
    const long long tag = r.integer(t[0], "an element tag");
    std::array<int, 4> nodes{};
    for (std::size_t a = 0; a < per; ++a) {
      const long long node = r.integer(t[1 + a], "a node tag");
      const auto it = data.node_index.find(node);
      if (it == data.node_index.end())
        r.fail("element " + std::to_string(tag) + " uses node " + std::to_string(node) +
               ", which $Nodes does not list");
      nodes[a] = it->second;
    }
    keepElement(data, type, entity, tag, r.lineNumber(), nodes);
  }
  return n;
}

/// Skips a section this reader does not use ($Periodic, $NodeData, ...) up to its end marker.
void skipSection(LineReader& r, const std::string& header) {
  const std::string end = "$End" + header.substr(1);
  while (r.next())
    if (r.line() == end) return;
  r.failFile("truncated file (expected " + end + ")");
}

}  // namespace

GmshData readSections(std::istream& in, const std::string& source_name, int dimension, bool body_required) {
  LineReader r(in, source_name);
  if (!r.next()) r.failFile("empty file (expected $MeshFormat)");
  if (r.line() != "$MeshFormat")
    r.fail("not a Gmsh mesh: expected $MeshFormat, found " + quote(r.line()));
  readMeshFormat(r);
  GmshData data;
  data.dimension = dimension;
  std::map<std::string, bool> seen;
  while (r.next()) {
    const std::string header = r.line();
    if (header[0] != '$') r.fail("expected a section such as $Nodes, found " + quote(header));
    if (header.rfind("$End", 0) == 0) r.fail("unexpected " + quote(header));
    if (seen[header]) r.fail("second " + header + " section");
    seen[header] = true;
    r.enterSection(header);
    if (header == "$PhysicalNames") readPhysicalNames(r, data);
    else if (header == "$Entities") readEntities(r, data);
    else if (header == "$Nodes") readBlocks(r, data, "node", readNodeBlock);
    else if (header == "$Elements" && !seen["$Nodes"]) r.fail("$Elements before $Nodes");
    else if (header == "$Elements") readBlocks(r, data, "element", readElementBlock);
    else skipSection(r, header);
  }
  if (!seen["$Nodes"]) r.failFile("no $Nodes section (truncated file?)");
  if (!seen["$Elements"]) r.failFile("no $Elements section (truncated file?)");
  if (dimension == 2 && data.triangles.empty())
    r.failFile("no triangles (with Mesh.SaveAll = 0, Gmsh saves only the elements of physical "
               "groups: is there a Physical Surface?)");
  if (dimension == 3 && body_required && data.tets.empty())
    r.failFile("no tetrahedra (with Mesh.SaveAll = 0, Gmsh saves only the elements of physical "
               "groups: is there a Physical Volume?)");
  return data;
}

std::ifstream openMeshFile(const std::filesystem::path& file) {
  std::error_code ec;
  // A device (/dev/zero) or a pipe would be read without end.
  if (std::filesystem::exists(file, ec) && !std::filesystem::is_directory(file, ec) &&
      !std::filesystem::is_regular_file(file, ec))
    throw InputError("mesh file '" + file.string() + "' is not a regular file (a device, a pipe or a socket)");
  std::ifstream in(file);
  if (!in || std::filesystem::is_directory(file, ec)) {
    const std::string message = "cannot open mesh file '" + file.string() + "'";
    if (MissingFileError::isMissing(file)) throw MissingFileError(message, file.string());
    throw InputError(message);
  }
  return in;
}

}  // namespace stc::detail

namespace stc {
namespace {

using detail::GmshData;
using detail::RawEdge;

/// Keeps the nodes that triangles use (renumbered in file order) and orients the triangles.
void buildNodesAndTriangles(const GmshData& data, std::vector<int>& index, TriMesh& mesh) {
  int used = 0;
  index = detail::usedNodeIndex(data.coords.size(), data.triangles, used);
  mesh.nodes.resize(2, used);
  mesh.node_tags.resize(static_cast<std::size_t>(used));
  for (std::size_t i = 0; i < index.size(); ++i)
    if (index[i] >= 0) {
      mesh.nodes.col(index[i]) = data.coords[i].head<2>();
      mesh.node_tags[static_cast<std::size_t>(index[i])] = data.node_tags[i];
    }
  mesh.triangles.resize(3, static_cast<Eigen::Index>(data.triangles.size()));
  for (std::size_t e = 0; e < data.triangles.size(); ++e)
    for (int a = 0; a < 3; ++a) mesh.triangles(a, e) = index[data.triangles[e][a]];
  bool all_clockwise = mesh.numElements() > 0;
  for (int e = 0; e < mesh.numElements() && all_clockwise; ++e)
    all_clockwise = mesh.twiceSignedArea(e) < 0;
  if (all_clockwise) mesh.triangles.row(1).swap(mesh.triangles.row(2));
}

/// After orientation: a triangle that is still clockwise (mixed orientation), or flat, is named by
/// its Gmsh element tag and line, which a user can find in the file (TriMesh::validate, which runs
/// next, only knows the position in the mesh). Flat: |area| <= 1e-12 x the mean, as validate.
void checkTriangles(const GmshData& data, const TriMesh& mesh, const std::string& source) {
  double mean = 0.0;
  for (int e = 0; e < mesh.numElements(); ++e) mean += std::abs(mesh.twiceSignedArea(e));
  mean /= std::max(1, mesh.numElements());
  for (int e = 0; e < mesh.numElements(); ++e) {
    const double area2 = mesh.twiceSignedArea(e);
    const bool flat = !(std::abs(area2) > 1e-12 * mean);
    if (!flat && area2 > 0.0) continue;
    const auto [tag, line] = data.triangle_origin[static_cast<std::size_t>(e)];
    throw InputError(source + ": line " + std::to_string(line) + ": triangle " + std::to_string(tag) +
                     (flat ? " is degenerate (zero area)"
                           : " is inverted (its nodes run clockwise, the other triangles' counter-clockwise)"));
  }
}

/// Per undirected edge {a < b}: how many triangles have it (1 on the body's boundary, 2 inside).
using EdgeUse = std::map<std::array<int, 2>, int>;

std::array<int, 2> undirected(int a, int b) { return {std::min(a, b), std::max(a, b)}; }

/// Conforming triangles (all counter-clockwise once checkTriangles has passed): a directed edge
/// a → b belongs to one triangle at most, since an interior edge is shared by two triangles that run
/// it in opposite directions, one on each side. A second triangle with the same directed edge lies
/// on the same side as the first: the two repeat or overlap each other, which would count the
/// material twice. Named by both Gmsh tags and the edge's node tags. Returns each edge's use count.
EdgeUse checkConforming(const GmshData& data, const std::vector<int>& index, const TriMesh& mesh,
                        const std::string& source) {
  std::vector<long long> tag_of(static_cast<std::size_t>(mesh.numNodes()));
  for (std::size_t i = 0; i < index.size(); ++i)
    if (index[i] >= 0) tag_of[static_cast<std::size_t>(index[i])] = data.node_tags[i];
  std::map<std::array<int, 2>, int> owner;  // directed edge → triangle
  EdgeUse uses;
  for (int e = 0; e < mesh.numElements(); ++e)
    for (int a = 0; a < 3; ++a) {
      const int i = mesh.triangles(a, e), j = mesh.triangles((a + 1) % 3, e);
      const auto [it, first] = owner.emplace(std::array<int, 2>{i, j}, e);
      ++uses[undirected(i, j)];
      if (first) continue;
      const auto [tag, line] = data.triangle_origin[static_cast<std::size_t>(e)];
      const long long other = data.triangle_origin[static_cast<std::size_t>(it->second)].first;
      const bool same = std::is_permutation(&mesh.triangles(0, e), &mesh.triangles(0, e) + 3, &mesh.triangles(0, it->second));
      throw InputError(source + ": line " + std::to_string(line) + ": triangle " + std::to_string(tag) +
                       (same ? " repeats triangle " + std::to_string(other) + " (the same three nodes)"
                             : " overlaps triangle " + std::to_string(other) + " (both lie on the same side of " +
                                   "their edge from node " + std::to_string(tag_of[i]) + " to node " +
                                   std::to_string(tag_of[j]) + ")"));
    }
  return uses;
}

/// Turns the line elements of every curve into edges of that curve's named physical groups. Each
/// must be an edge of exactly one triangle (on the body's boundary: contact, loads and normals are
/// defined there) and appear once in a group (a repeated edge would count its length twice).
void buildGroups(const GmshData& data, const std::vector<int>& index, const EdgeUse& uses, const std::string& source,
                 TriMesh& mesh) {
  std::map<std::string, std::set<std::array<int, 2>>> seen;  // per group, its edges so far
  for (const auto& [curve, edges] : data.curve_edges) {
    const auto groups = data.curve_groups.find(curve);
    if (groups == data.curve_groups.end())
      throw InputError(source + ": line " + std::to_string(edges.front().line) +
                       ": line elements on curve " + std::to_string(curve) +
                       ", which $Entities does not list");
    for (long long physical : groups->second) {
      const auto named = data.names.find({1, physical});
      const std::string name = named == data.names.end() ? std::to_string(physical) : named->second;
      for (const RawEdge& edge : edges) {
        for (int node : edge.nodes)
          if (index[node] < 0)
            throw InputError(source + ": line " + std::to_string(edge.line) + ": element " +
                             std::to_string(edge.tag) + " of boundary '" + name + "' uses node " +
                             std::to_string(data.node_tags[node]) + ", which no triangle uses");
        const std::array<int, 2> key = undirected(index[edge.nodes[0]], index[edge.nodes[1]]);
        const auto use = uses.find(key);
        const int triangles = use == uses.end() ? 0 : use->second;
        const std::string element = source + ": line " + std::to_string(edge.line) + ": element " +
                                    std::to_string(edge.tag) + " of boundary '" + name + "'";
        if (triangles != 1)
          throw InputError(element + (triangles == 0 ? " is not an edge of any triangle"
                                                     : " lies inside the body (two triangles share it): a boundary "
                                                       "group holds edges of the body's boundary only"));
        if (!seen[name].insert(key).second) throw InputError(element + " repeats an edge already in it");
        mesh.groups[name].edges.push_back({index[edge.nodes[0]], index[edge.nodes[1]]});
      }
    }
  }
}

}  // namespace

TriMesh parseGmsh(std::istream& in, const std::string& source_name) {
  const GmshData data = detail::readSections(in, source_name, 2);
  TriMesh mesh;
  std::vector<int> index;
  buildNodesAndTriangles(data, index, mesh);
  checkTriangles(data, mesh, source_name);
  const EdgeUse uses = checkConforming(data, index, mesh, source_name);
  buildGroups(data, index, uses, source_name, mesh);
  detail::finishMesh(mesh, source_name);
  return mesh;
}

TriMesh readGmsh(const std::filesystem::path& file) {
  std::ifstream in = detail::openMeshFile(file);
  return parseGmsh(in, file.string());
}

}  // namespace stc
