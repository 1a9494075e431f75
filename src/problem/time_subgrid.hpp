#pragma once
// The same problem on some of its instants (docs/method.md §5, "Nested iteration in time"). The
// loading is stored sampled on the grid (SeparatedLoad::values), so keeping the instants t_{k_j}
// keeps its exact values there: the problem on the sub-grid is the scene with those instants only.
// Its solution, interpolated back, starts the iteration on the whole grid
// (fas/apriori/nested_in_time.hpp).
#include <vector>

#include "stcontact/problem/problem.hpp"

namespace stc {

/// The instants 0, q, 2q, … of a grid of m instants, and the last, m − 1, when q does not divide it
/// (increasing). Throws std::invalid_argument for m < 1 or q < 1.
std::vector<int> everyNthInstant(int m, int q);

/// `problem` on the instants `kept` (increasing, within [0, m)): the same body, contact interface and
/// stiffness, the times and the load histories taken at those instants. Throws
/// std::invalid_argument when `kept` is empty, unordered or out of range.
Problem onInstants(const Problem& problem, const std::vector<int>& kept);

}  // namespace stc
