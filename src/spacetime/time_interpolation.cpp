#include "stcontact/spacetime/time_interpolation.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace stc {
namespace {

void requireGrid(const InterfaceHistory& history, const std::vector<double>& times, const std::vector<double>& onto) {
  if (times.empty() || history.numSteps() != static_cast<int>(times.size()) || history.lambda.cols() != history.v.cols())
    throw std::invalid_argument("interpolatedInTime: the history has " + std::to_string(history.numSteps()) +
                                " instants, its grid " + std::to_string(times.size()));
  if (!std::is_sorted(times.begin(), times.end()) ||
      std::adjacent_find(times.begin(), times.end()) != times.end())
    throw std::invalid_argument("interpolatedInTime: the history's instants must increase");
  for (double t : onto)
    if (t < times.front() || t > times.back())
      throw std::invalid_argument("interpolatedInTime: instant " + std::to_string(t) + " outside [" +
                                  std::to_string(times.front()) + ", " + std::to_string(times.back()) + "]");
}

}  // namespace

InterfaceHistory interpolatedInTime(const InterfaceHistory& history, const std::vector<double>& times,
                                    const std::vector<double>& onto) {
  requireGrid(history, times, onto);
  const auto n = static_cast<Eigen::Index>(onto.size());
  InterfaceHistory out{Eigen::MatrixXd(history.v.rows(), n), Eigen::MatrixXd(history.lambda.rows(), n)};
  if (times.size() == 1) {  // one instant: onto holds it alone
    out.v.colwise() = history.v.col(0);
    out.lambda.colwise() = history.lambda.col(0);
    return out;
  }
  const auto last_interval = static_cast<std::ptrdiff_t>(times.size()) - 2;
  for (Eigen::Index i = 0; i < n; ++i) {
    const double t = onto[static_cast<size_t>(i)];
    // j: the last instant of `times` at or before t, but not the last one (t = t_{m−1} takes a = 1).
    const std::ptrdiff_t at = std::upper_bound(times.begin(), times.end(), t) - times.begin() - 1;
    const auto j = static_cast<size_t>(std::clamp<std::ptrdiff_t>(at, 0, last_interval));
    const double a = (t - times[j]) / (times[j + 1] - times[j]);
    const auto c = static_cast<Eigen::Index>(j);
    out.v.col(i) = (1.0 - a) * history.v.col(c) + a * history.v.col(c + 1);
    out.lambda.col(i) = (1.0 - a) * history.lambda.col(c) + a * history.lambda.col(c + 1);
  }
  return out;
}

}  // namespace stc
