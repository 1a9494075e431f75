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
/// their arc or curved surface, and the memory of a solve whatever its backend, 12 bytes per stored
/// entry of kMatrixCopies matrices of about 14 entries per row in 2D and 45 in 3D, and 10 interface
/// histories of d n_C × m doubles (iterates, local stages, differences, directions).
SizeEstimate estimateSize(const ModelSpec& scene);

/// The matrices every solve holds, in copies of K's entries: K, K_ff and K + BᵀkB (3), and an
/// iterative backend's own copy and AMG hierarchy (4.7 measured: CG + GAMG at 1.05M dofs, one rank,
/// 2.72 GB, docs/linear_solvers.md, "A million degrees of freedom"), 8 in all. A direct factor's fill is left
/// to its own analysis, which knows it before any numerical work (prepareSpdSolver: `auto` gives way
/// to CG + GAMG beyond its bound, a factor asked for by name is refused beyond the memory available):
/// the 3D fill, 20 times K's entries and more as the body grows, would refuse here runs that CG +
/// GAMG makes (the fretting history at 10⁶ dofs).
inline constexpr double kMatrixCopies = 8.0;

/// Throws InputError naming the size keys when estimateSize(scene).bytes exceeds the memory the
/// process may still allocate (src/core/memory.hpp), or the address-space limit is below any run's.
void requireFitsInMemory(const ModelSpec& scene);

}  // namespace stc
