#pragma once
// Growth exponents of a scaling study (docs/scaling.md): the power law t = C · s^p fitted by least
// squares on log-log axes, log t = log C + p log s (GSL gsl_fit_linear), and where two such laws cross.
#include <optional>
#include <vector>

namespace stc {

struct PowerLawFit {
  int points = 0;           ///< sizes used (every size and value must be > 0)
  double exponent = 0.0;    ///< p, the slope on log-log axes
  double log_prefactor = 0.0;  ///< log C (natural log)
  /// Standard error of p from the scatter about the line, sqrt(cov11) of gsl_fit_linear, which
  /// estimates the residual variance as sumsq / (n − 2): undefined (NaN) for two points.
  double exponent_stderr = 0.0;
  double residual_sumsq = 0.0;  ///< sum of squared residuals of log t

  /// C · s^p.
  double at(double size) const;
};

/// Least-squares fit of log(values) against log(sizes). Throws std::invalid_argument for fewer than
/// two points, different lengths, a non-positive entry, or all sizes equal.
PowerLawFit fitPowerLaw(const std::vector<double>& sizes, const std::vector<double>& values);

/// The size s > 0 at which a.at(s) = b.at(s): log s = (log C_b − log C_a) / (p_a − p_b). Empty when
/// the exponents are equal (parallel lines on log-log axes).
std::optional<double> crossingSize(const PowerLawFit& a, const PowerLawFit& b);

}  // namespace stc
