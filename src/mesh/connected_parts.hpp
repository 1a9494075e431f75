#pragma once
// The connected parts of a mesh: the bodies of a scene (one, or two in contact, docs/two_bodies.md).
// Two nodes are in one part when a chain of elements joins them.
#include <vector>

#include "stcontact/mesh/body_mesh.hpp"

namespace stc {

/// The part of each node, 0 … number of parts − 1, numbered by their first node.
std::vector<int> partOfNodes(const BodyMesh& body);

/// The nodes of each part, increasing.
std::vector<std::vector<int>> connectedParts(const BodyMesh& body);

}  // namespace stc
