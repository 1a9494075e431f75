#pragma once
// Two identical bodies facing each other (docs/scene_format.md, `mesh.mirror_gap`): the body and its
// mirror image across the plane x_d = z_min − gap / 2 normal to the last axis (y in 2D, z in 3D),
// z_min the body's lowest coordinate along it, so that the lowest points of the two bodies are
// `gap` apart. The image's nodes and elements follow the body's (ids offset by its counts; each
// element's first two nodes swapped, so that it keeps a positive measure) and its boundary groups
// are the body's named "mirror_" + name. Two identical elastic bodies have Dundurs constant β = 0:
// Hertz and Cattaneo–Mindlin are exact for them (K. L. Johnson, Contact Mechanics, §5.6, §7.2).
#include "stcontact/mesh/body_mesh.hpp"

namespace stc {

/// The prefix of the image's group names.
inline constexpr const char* kMirrorPrefix = "mirror_";

/// The body and its mirror image `gap` (≥ 0) below it; throws InputError when the body already
/// has a group named with the prefix.
BodyMesh withMirrorImage(const BodyMesh& body, double gap);

}  // namespace stc
