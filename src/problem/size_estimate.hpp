#pragma once
// The size of a scene's problem before anything is built, and the memory a solve of it needs
// (order of magnitude), so that a scene that cannot fit is refused with its keys named instead of
// allocating until the machine gives out (mesh.arc_nodes = 10^7 took 12 GB, time.steps = 10^8
// ended in bad_alloc, mesh.arc_nodes = 2³¹ − 1 overflowed the generator's node numbering).
#include "stcontact/scene/model_spec.hpp"

namespace stc {

struct SizeEstimate {
  double nodes = 0.0;          ///< of the mesh (0: a Gmsh file, read as it is)
  double contact_rows = 0.0;   ///< d × potential contact nodes (0: unknown before the file is read)
  double bytes = 0.0;          ///< a solve's memory: the stiffness matrices and factor, the interface histories
};

/// Counts in floating point, so that no size overflows: the generators' node counts as they would
/// build them (halfDiscNodeCount, halfBallNodeCount), the potential contact nodes on
/// their arc or curved surface, and the memory of a solve, 12 bytes per stored entry of the
/// matrices (K, K_ff, K + BᵀkB and the factor's fill, about 14 entries per row in 2D and 45 in 3D,
/// the factor 5 and 20 times those) and 10 interface histories of d n_C × m doubles (iterates, local
/// stages, differences, directions).
SizeEstimate estimateSize(const ModelSpec& scene);

/// Throws InputError naming the size keys when estimateSize(scene).bytes exceeds the memory the
/// process may still allocate (src/core/memory.hpp), or the address-space limit is below any run's.
void requireFitsInMemory(const ModelSpec& scene);

}  // namespace stc
