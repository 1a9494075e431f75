#include "stcontact/studies/growth_fit.hpp"

#include <gsl/gsl_fit.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace stc {

double PowerLawFit::at(double size) const { return std::exp(log_prefactor + exponent * std::log(size)); }

PowerLawFit fitPowerLaw(const std::vector<double>& sizes, const std::vector<double>& values) {
  if (sizes.size() != values.size()) throw std::invalid_argument("power-law fit: sizes and values differ in length");
  if (sizes.size() < 2) throw std::invalid_argument("power-law fit: needs at least two points");
  std::vector<double> x, y;
  for (std::size_t i = 0; i < sizes.size(); ++i) {
    if (!(sizes[i] > 0.0) || !(values[i] > 0.0)) throw std::invalid_argument("power-law fit: sizes and values must be > 0");
    x.push_back(std::log(sizes[i]));
    y.push_back(std::log(values[i]));
  }
  if (std::all_of(x.begin(), x.end(), [&](double v) { return v == x.front(); }))
    throw std::invalid_argument("power-law fit: all sizes are equal");
  PowerLawFit fit;
  fit.points = static_cast<int>(x.size());
  double cov00 = 0.0, cov01 = 0.0, cov11 = 0.0;
  gsl_fit_linear(x.data(), 1, y.data(), 1, x.size(), &fit.log_prefactor, &fit.exponent, &cov00, &cov01, &cov11,
                 &fit.residual_sumsq);
  fit.exponent_stderr = fit.points > 2 ? std::sqrt(cov11) : std::numeric_limits<double>::quiet_NaN();
  return fit;
}

std::optional<double> crossingSize(const PowerLawFit& a, const PowerLawFit& b) {
  const double dp = a.exponent - b.exponent;
  if (dp == 0.0) return std::nullopt;
  return std::exp((b.log_prefactor - a.log_prefactor) / dp);
}

}  // namespace stc
