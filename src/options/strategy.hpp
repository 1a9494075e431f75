#pragma once
// The solution strategies, parsed from their names at the edges (the scene's solver.name, the command
// line's --solver and --solvers, the Python module's solver=) and dispatched by the registry
// (strategies/registry.hpp). docs/interface.md describes each.
#include <array>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace stc {

enum class Strategy { Latin, LatinPgd, FasAposteriori, FasApriori, Incremental };

/// Each strategy and its name, in the order of the comparison reports.
inline constexpr std::array<std::pair<std::string_view, Strategy>, 5> kStrategies = {{
    {"latin", Strategy::Latin},
    {"latin-pgd", Strategy::LatinPgd},
    {"fas-aposteriori", Strategy::FasAposteriori},
    {"fas-apriori", Strategy::FasApriori},
    {"incremental", Strategy::Incremental},
}};

/// "latin", "latin-pgd", ...
std::string_view nameOf(Strategy strategy);
/// The strategy of `name`; InputError "unknown solver 'NAME' (known: latin, ...)" otherwise.
Strategy strategyNamed(std::string_view name);
/// Every name, in the order of kStrategies.
std::vector<std::string> strategyNames();
/// The names of `strategies`, in order.
std::vector<std::string> strategyNamesOf(const std::vector<Strategy>& strategies);
/// The names of `strategies` joined by `separator` ("latin,incremental").
std::string joinedNames(const std::vector<Strategy>& strategies, std::string_view separator = ",");

}  // namespace stc
