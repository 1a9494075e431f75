#pragma once
// What the triangle mesh (src/mesh/tri_mesh.hpp) and the tetrahedron mesh (src/mesh/tet_mesh.hpp)
// do alike with their elements and named boundary groups: look a group up, collect its nodes,
// check node ids and element measures, find the boundary's faces. A group holds faces (edges in 2D,
// triangles in 3D) in the member `Group::*faces` and their nodes in `nodes`.
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "stcontact/core/input_error.hpp"

namespace stc::mesh_checks {

/// Range of the mean element measure (area or volume) checked below: a measure is a product of d
/// coordinate differences, computed reliably far from double's limits (2.2e-308, 1.8e308) only.
inline constexpr double kSmallestMeasure = 1e-200;
inline constexpr double kLargestMeasure = 1e200;

/// `value` in the shortest of fixed or scientific notation (6 significant digits), for messages.
inline std::string numberText(double value) {
  std::ostringstream text;
  text << value;
  return text.str();
}

/// The group named `name`; throws InputError listing the groups there are.
template <class Group>
const Group& findGroup(const std::map<std::string, Group>& groups, const std::string& name) {
  auto it = groups.find(name);
  if (it != groups.end()) return it->second;
  std::ostringstream msg;
  msg << "boundary '" << name << "' is not in the mesh (it has:";
  for (const auto& [key, value] : groups) msg << " '" << key << "'";
  msg << ")";
  throw InputError(msg.str());
}

/// The faces that belong to exactly one element, as `face(e, f)` orients them (f < faces_per_element):
/// an interior face is met twice, once from each side. In the order of their sorted node ids.
template <std::size_t N, class Face>
std::vector<std::array<int, N>> facesOfOneElement(int elements, int faces_per_element, Face&& face) {
  std::map<std::array<int, N>, std::array<int, N>> once;  // sorted ids → oriented face
  for (int e = 0; e < elements; ++e)
    for (int f = 0; f < faces_per_element; ++f) {
      const std::array<int, N> oriented = face(e, f);
      std::array<int, N> key = oriented;
      std::sort(key.begin(), key.end());
      auto [it, inserted] = once.emplace(key, oriented);
      if (!inserted) once.erase(it);
    }
  std::vector<std::array<int, N>> faces;
  faces.reserve(once.size());
  for (const auto& [key, oriented] : once) faces.push_back(oriented);
  return faces;
}

/// Fills `nodes` of every group from its faces (sorted, unique).
template <class Group, class Face>
void finalizeGroupNodes(std::map<std::string, Group>& groups, std::vector<Face> Group::*faces) {
  for (auto& [name, g] : groups) {
    for (const auto& face : g.*faces) g.nodes.insert(g.nodes.end(), face.begin(), face.end());
    std::sort(g.nodes.begin(), g.nodes.end());
    g.nodes.erase(std::unique(g.nodes.begin(), g.nodes.end()), g.nodes.end());
  }
}

/// Throws InputError naming the first element (a column of `elements`) with a node id out of range.
template <class Elements>
void checkElementNodeIds(const Elements& elements, int num_nodes) {
  for (int e = 0; e < static_cast<int>(elements.cols()); ++e)
    for (int a = 0; a < static_cast<int>(elements.rows()); ++a)
      if (elements(a, e) < 0 || elements(a, e) >= num_nodes)
        throw InputError("element " + std::to_string(e) + " refers to node " + std::to_string(elements(a, e)) +
                         ", which does not exist");
}

/// Throws InputError naming the first group whose faces hold a node id out of range.
template <class Group, class Face>
void checkGroupNodeIds(const std::map<std::string, Group>& groups, std::vector<Face> Group::*faces,
                       int num_nodes) {
  for (const auto& [name, g] : groups)
    for (const auto& face : g.*faces)
      for (int id : face)
        if (id < 0 || id >= num_nodes)
          throw InputError("boundary '" + name + "' refers to node " + std::to_string(id) +
                           ", which does not exist");
}

/// Throws InputError naming the first element whose signed measure `measure(e)` (area or volume)
/// is below 1e-12 of the mean |measure| ("degenerate (<what> m)") or negative ("inverted
/// (<inverted_what> m)").
template <class Measure>
void checkElementMeasures(int num_elements, Measure measure, const std::string& what,
                          const std::string& inverted_what) {
  double mean = 0.0;
  for (int e = 0; e < num_elements; ++e) mean += std::abs(measure(e));
  mean /= num_elements;
  // Coordinates near the ends of double's range give measures (∝ size^d) that overflow or underflow.
  if (!(mean >= kSmallestMeasure && mean <= kLargestMeasure)) {
    std::ostringstream msg;
    msg << "the elements' mean " << what << " is "
        << (std::isfinite(mean) ? numberText(mean) + ": outside [1e-200, 1e200], it is" : std::string("not finite:"))
        << " not computed reliably in double precision; state the mesh in other units (coordinates between about "
           "1e-60 and 1e60)";
    throw InputError(msg.str());
  }
  for (int e = 0; e < num_elements; ++e) {
    const double m = measure(e);
    if (!(std::abs(m) > 1e-12 * mean))
      throw InputError("element " + std::to_string(e) + " is degenerate (" + what + " " + numberText(m) + ")");
    if (m < 0)
      throw InputError("element " + std::to_string(e) + " is inverted (" + inverted_what + " " + numberText(m) +
                       ")");
  }
}

}  // namespace stc::mesh_checks
