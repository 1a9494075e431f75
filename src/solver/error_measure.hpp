#pragma once
// What the iteration monitor needs of a true-error measure (docs/method.md §2): the relative error of an
// equilibrated iterate given by its contact forces. ErrorReference measures it against a reference
// solution; a solve on part of the interface measures its iterates through ErrorOnRows.
#include <Eigen/Core>

namespace stc {

class ErrorMeasure {
 public:
  virtual ~ErrorMeasure() = default;
  /// Relative energy error of the iterate with contact forces `lambda`; NaN when undefined.
  virtual double relativeError(const Eigen::MatrixXd& lambda) const = 0;
  /// False when the measure has no meaning (a reference without strain energy).
  virtual bool defined() const = 0;
};

}  // namespace stc
