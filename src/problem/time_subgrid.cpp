#include "stcontact/problem/time_subgrid.hpp"

#include <stdexcept>
#include <string>

namespace stc {

std::vector<int> everyNthInstant(int m, int q) {
  if (m < 1 || q < 1)
    throw std::invalid_argument("everyNthInstant: needs m >= 1 and q >= 1 (m = " + std::to_string(m) +
                                ", q = " + std::to_string(q) + ")");
  std::vector<int> kept;
  for (int k = 0; k < m; k += q) kept.push_back(k);
  if (kept.back() != m - 1) kept.push_back(m - 1);
  return kept;
}

Problem onInstants(const Problem& problem, const std::vector<int>& kept) {
  const int m = problem.numSteps();
  if (kept.empty()) throw std::invalid_argument("onInstants: no instant kept");
  for (size_t j = 0; j < kept.size(); ++j)
    if (kept[j] < 0 || kept[j] >= m || (j > 0 && kept[j] <= kept[j - 1]))
      throw std::invalid_argument("onInstants: the instants kept must increase within [0, " + std::to_string(m) +
                                  ")");
  Problem sub = problem;
  sub.times.clear();
  for (int k : kept) sub.times.push_back(problem.times[static_cast<size_t>(k)]);
  for (SeparatedLoad& load : sub.loads) {
    std::vector<double> values;
    values.reserve(kept.size());
    for (int k : kept) values.push_back(load.values[static_cast<size_t>(k)]);
    load.values = std::move(values);
  }
  return sub;
}

}  // namespace stc
