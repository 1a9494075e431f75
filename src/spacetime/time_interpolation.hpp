#pragma once
// Interface histories carried from one time grid to a finer one (docs/method.md §5, "Nested
// iteration in time"): linear interpolation in time, instant by instant,
//   h(t) = (1 − a) h(t_j) + a h(t_{j+1}),   a = (t − t_j) / (t_{j+1} − t_j),   t_j ≤ t ≤ t_{j+1}.
// Exact for histories linear between the instants of the first grid, as the scenes' loadings are.
#include <vector>

#include "stcontact/spacetime/interface_history.hpp"

namespace stc {

/// `history`, sampled on `times` (increasing), interpolated at `onto` (within [times.front(),
/// times.back()]). Throws std::invalid_argument for sizes that do not match, times that do not
/// increase or an instant of `onto` outside the first grid.
InterfaceHistory interpolatedInTime(const InterfaceHistory& history, const std::vector<double>& times,
                                    const std::vector<double>& onto);

}  // namespace stc
