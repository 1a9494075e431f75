#include "stcontact/mesh/half_disc_slab.hpp"

#include <algorithm>
#include <map>
#include <string>

#include "stcontact/core/input_error.hpp"
#include "stcontact/mesh/detail/prism_split.hpp"

namespace stc {
namespace {

// Names the boundary triangles: on a face z = const, "front" or "back"; on a side, the half-disc
// groups that hold the edge the triangle's nodes project onto.
void addGroups(const TriMesh& section, double thickness, TetMesh& slab) {
  const int n2d = section.numNodes();
  std::map<std::array<int, 2>, std::vector<std::string>> edgeGroups;
  for (const auto& [name, group] : section.groups)
    for (auto edge : group.edges) {
      std::sort(edge.begin(), edge.end());
      edgeGroups[edge].push_back(name);
    }
  for (const auto& t : boundaryTriangles(slab)) {
    const auto onPlane = [&](double z) {
      return std::all_of(t.begin(), t.end(), [&](int n) { return slab.nodes(2, n) == z; });
    };
    if (onPlane(0.0)) slab.groups["front"].triangles.push_back(t);
    else if (onPlane(thickness)) slab.groups["back"].triangles.push_back(t);
    else {
      std::array<int, 3> in2d{t[0] % n2d, t[1] % n2d, t[2] % n2d};
      std::sort(in2d.begin(), in2d.end());
      const std::array<int, 2> edge{in2d[0], in2d[0] == in2d[1] ? in2d[2] : in2d[1]};
      const auto it = edgeGroups.find(edge);
      if (it == edgeGroups.end()) continue;  // a side of the section that no group names
      for (const std::string& name : it->second) slab.groups[name].triangles.push_back(t);
    }
  }
  slab.finalizeGroups();
}

}  // namespace

void HalfDiscSlabOptions::validate() const {
  section.validate();
  if (!(thickness > 0.0) || !std::isfinite(thickness))
    throw InputError("half_disc_slab: thickness = " + std::to_string(thickness) + " must be > 0");
  if (layers < 1) throw InputError("half_disc_slab: layers = " + std::to_string(layers) + " must be >= 1");
}

TetMesh makeHalfDiscSlab(const HalfDiscSlabOptions& options) {
  options.validate();
  const TriMesh section = makeHalfDisc(options.section);
  const int n2d = section.numNodes(), layers = options.layers;
  TetMesh slab;
  slab.nodes.resize(3, static_cast<Eigen::Index>(n2d) * (layers + 1));
  for (int l = 0; l <= layers; ++l) {
    const double z = l == layers ? options.thickness : options.thickness * l / layers;
    for (int n = 0; n < n2d; ++n) slab.nodes.col(n + l * n2d) << section.nodes.col(n), z;
  }
  std::vector<std::array<int, 4>> tets;
  tets.reserve(3 * static_cast<std::size_t>(section.numElements()) * layers);
  for (int l = 0; l < layers; ++l)
    for (int e = 0; e < section.numElements(); ++e) {
      std::array<int, 3> t{section.triangles(0, e), section.triangles(1, e), section.triangles(2, e)};
      std::sort(t.begin(), t.end());
      detail::splitPrism({t[0] + l * n2d, t[1] + l * n2d, t[2] + l * n2d},
                         {t[0] + (l + 1) * n2d, t[1] + (l + 1) * n2d, t[2] + (l + 1) * n2d}, tets);
    }
  slab.tets.resize(4, static_cast<Eigen::Index>(tets.size()));
  for (std::size_t e = 0; e < tets.size(); ++e) slab.tets.col(e) << tets[e][0], tets[e][1], tets[e][2], tets[e][3];
  for (int e = 0; e < slab.numElements(); ++e)  // the prism split does not orient
    if (slab.sixSignedVolume(e) < 0.0) std::swap(slab.tets(2, e), slab.tets(3, e));
  addGroups(section, options.thickness, slab);
  slab.validate();
  return slab;
}

}  // namespace stc
