#include "stcontact/problem/size_estimate.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "stcontact/core/input_error.hpp"
#include "stcontact/core/memory.hpp"
#include "stcontact/mesh/half_ball.hpp"
#include "stcontact/mesh/half_disc.hpp"

namespace stc {
namespace {

/// Potential contact nodes: the arc's, the slab's arc on each layer, the half-ball's curved surface.
double contactNodes(const MeshSpec& spec, double nodes) {
  if (spec.generator == "half_disc") return spec.arc_nodes;
  if (spec.generator == "half_disc_slab") return double(spec.arc_nodes) * (spec.layers + 1);
  if (spec.generator == "half_ball") return std::min(nodes, 6.0 * std::pow(nodes, 2.0 / 3.0));
  return 0.0;
}

std::string sizeKeys(const ModelSpec& scene) {
  std::ostringstream keys;
  const MeshSpec& m = scene.mesh;
  if (m.generator == "half_disc") keys << "mesh.arc_nodes = " << m.arc_nodes << ", mesh.grading = " << m.grading;
  else if (m.generator == "half_disc_slab") keys << "mesh.arc_nodes = " << m.arc_nodes << ", mesh.layers = " << m.layers;
  else if (m.generator == "half_ball") keys << "mesh.divisions = " << m.divisions << ", mesh.core = " << m.core;
  else keys << "mesh.file";
  keys << ", time.steps = " << scene.time.steps;
  return keys.str();
}

}  // namespace

SizeEstimate estimateSize(const ModelSpec& scene) {
  SizeEstimate e;
  const MeshSpec& m = scene.mesh;
  const HalfDiscOptions section{m.radius, m.arc_nodes, m.grading};
  if (m.generator == "half_disc") e.nodes = halfDiscNodeCount(section);
  else if (m.generator == "half_disc_slab") e.nodes = halfDiscNodeCount(section) * (m.layers + 1.0);
  else if (m.generator == "half_ball") e.nodes = halfBallNodeCount({m.radius, m.divisions, m.grading, m.core});
  const int d = scene.dimension;
  e.contact_rows = d * contactNodes(m, e.nodes);
  if (m.mirror_gap) e.nodes *= 2.0;  // the body and its image (mesh/mirror_image.hpp)
  const double rows = d * e.nodes;
  const double entries_per_row = d == 3 ? 45.0 : 14.0;
  e.bytes = 12.0 * rows * entries_per_row * kMatrixCopies + 8.0 * 10.0 * e.contact_rows * scene.time.steps;
  return e;
}

void requireFitsInMemory(const ModelSpec& scene) {
  requireUsableAddressSpace();
  const SizeEstimate e = estimateSize(scene);
  const double available = availableMemoryBytes();
  if (e.bytes <= available) return;
  std::ostringstream msg;
  msg.precision(3);
  msg << "the problem does not fit in memory: " << sizeKeys(scene) << " give about " << e.nodes << " nodes and "
      << e.contact_rows << " interface rows over " << scene.time.steps << " instants, a solve of about "
      << bytesText(e.bytes) << ", and " << bytesText(available)
      << " are available: reduce the mesh or the number of instants";
  throw InputError(msg.str());
}

}  // namespace stc
