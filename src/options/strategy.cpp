#include "stcontact/options/strategy.hpp"

#include "stcontact/core/input_error.hpp"

namespace stc {

std::string_view nameOf(Strategy strategy) {
  for (const auto& [name, s] : kStrategies)
    if (s == strategy) return name;
  return "unknown";
}

Strategy strategyNamed(std::string_view name) {
  for (const auto& [known, s] : kStrategies)
    if (known == name) return s;
  std::string list;
  for (const auto& [known, s] : kStrategies) list += (list.empty() ? "" : ", ") + std::string(known);
  throw InputError("unknown solver '" + std::string(name) + "' (known: " + list + ")");
}

std::vector<std::string> strategyNames() {
  std::vector<std::string> names;
  for (const auto& [name, s] : kStrategies) names.emplace_back(name);
  return names;
}

std::vector<std::string> strategyNamesOf(const std::vector<Strategy>& strategies) {
  std::vector<std::string> names;
  for (const Strategy s : strategies) names.emplace_back(nameOf(s));
  return names;
}

std::string joinedNames(const std::vector<Strategy>& strategies, std::string_view separator) {
  std::string text;
  for (const Strategy s : strategies) text += (text.empty() ? "" : std::string(separator)) + std::string(nameOf(s));
  return text;
}

}  // namespace stc
