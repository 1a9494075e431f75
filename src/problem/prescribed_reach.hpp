#pragma once
// The potential contact nodes within reach of the prescribed motion: a contact search done before any
// solve (docs/method.md §5, "The reduced interface"). Each [[dirichlet]] history moves its dofs
// along one axis by the same amount (src/problem/problem.hpp, SeparatedLoad), so the prescribed
// motion is a translation w(t) = Σ_l values_l(t) a_l, a_l the axis of history l. A body that followed
// it rigidly would bring node i to the gap g0_i + n_i · w(t); the nodes whose gap it closes to within
// `margin` at some instant are those the contact can reach. Elastic deformation moves the nodes near
// the contact less than the rigid motion (the body is compressed there), so the set is usually a
// superset of the contact zone; it is a prediction, and the reduced interface checks the nodes it
// leaves out (src/strategies/reduced_interface.hpp).
#include <optional>
#include <vector>

#include "src/problem/problem.hpp"

namespace stc {

/// The nodes i (increasing) with g0_i + min_k n_i · w(t_k) ≤ margin. None (nullopt) when the loading
/// is not a prescribed translation alone: an applied force (whose reach needs a solve) or a history
/// whose prescribed dofs lie along more than one axis.
std::optional<std::vector<int>> nodesWithinPrescribedReach(const Problem& problem, double margin);

}  // namespace stc
