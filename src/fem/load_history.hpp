#pragma once
// A scalar history given at a few times, linear in between (GSL gsl_interp_linear),
// constant before the first and after the last given time.
#include <memory>
#include <vector>

#include "stcontact/scene/model_spec.hpp"

namespace stc {

class LoadHistory {
 public:
  explicit LoadHistory(const History& history);
  ~LoadHistory();
  LoadHistory(LoadHistory&&) noexcept;
  LoadHistory& operator=(LoadHistory&&) noexcept;

  double operator()(double t) const;
  /// Values at every instant of a grid.
  std::vector<double> sample(const std::vector<double>& times) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace stc
