#include "stcontact/fem/load_history.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_interp.h>

#include <stdexcept>

namespace stc {

struct LoadHistory::Impl {
  std::vector<double> times, values;
  gsl_interp* interp = nullptr;
  ~Impl() {
    if (interp) gsl_interp_free(interp);
  }
};

LoadHistory::LoadHistory(const History& history) : impl_(std::make_unique<Impl>()) {
  impl_->times = history.times;
  impl_->values = history.values;
  if (impl_->times.empty() || impl_->times.size() != impl_->values.size())
    throw std::invalid_argument("LoadHistory: times and values must be non-empty and of equal length");
  if (impl_->times.size() >= 2) {
    gsl_set_error_handler_off();  // report through the status code, never abort()
    impl_->interp = gsl_interp_alloc(gsl_interp_linear, impl_->times.size());
    if (!impl_->interp ||
        gsl_interp_init(impl_->interp, impl_->times.data(), impl_->values.data(), impl_->times.size()) != GSL_SUCCESS)
      throw std::invalid_argument("LoadHistory: times must be strictly increasing");
  }
}

LoadHistory::~LoadHistory() = default;
LoadHistory::LoadHistory(LoadHistory&&) noexcept = default;
LoadHistory& LoadHistory::operator=(LoadHistory&&) noexcept = default;

double LoadHistory::operator()(double t) const {
  const auto& ts = impl_->times;
  if (ts.size() == 1 || t <= ts.front()) return impl_->values.front();
  if (t >= ts.back()) return impl_->values.back();
  // gsl_interp_eval without an accelerator: a binary search per call, fine for grid sampling.
  return gsl_interp_eval(impl_->interp, ts.data(), impl_->values.data(), t, nullptr);
}

std::vector<double> LoadHistory::sample(const std::vector<double>& times) const {
  std::vector<double> out;
  out.reserve(times.size());
  for (double t : times) out.push_back((*this)(t));
  return out;
}

}  // namespace stc
