#include "stcontact/solver/warm_start.hpp"

#include <cmath>

#include <stdexcept>
#include <string>

namespace stc {
namespace {

std::string size(Eigen::Index rows, Eigen::Index cols) { return std::to_string(rows) + " × " + std::to_string(cols); }

}  // namespace

bool fitsProblem(const InterfaceHistory& history, const Problem& problem) {
  const Eigen::Index rows = problem.contact.rows(), cols = problem.numSteps();
  return history.v.rows() == rows && history.v.cols() == cols && history.lambda.rows() == rows &&
         history.lambda.cols() == cols;
}

bool fitsProblem(const Eigen::MatrixXd& directions, const Problem& problem) {
  return directions.rows() == problem.contact.rows();
}

void requireFinite(const Eigen::MatrixXd& values, const std::string& what) {
  for (Eigen::Index k = 0; k < values.cols(); ++k)
    for (Eigen::Index r = 0; r < values.rows(); ++r)
      if (!std::isfinite(values(r, k)))
        throw std::invalid_argument(what + " holds " + std::to_string(values(r, k)) + " at row " + std::to_string(r) +
                                    ", column " + std::to_string(k) + ": a warm start must be finite");
}

void requireFits(const InterfaceHistory& start, const Problem& problem) {
  if (!fitsProblem(start, problem))
    throw std::invalid_argument("start history is " + size(start.v.rows(), start.v.cols()) + " (v) and " +
                                size(start.lambda.rows(), start.lambda.cols()) + " (λ), the problem's interface " +
                                size(problem.contact.rows(), problem.numSteps()));
  requireFinite(start.v, "start history v");
  requireFinite(start.lambda, "start history λ");
}

void requireFits(const Eigen::MatrixXd& directions, const Problem& problem) {
  if (!fitsProblem(directions, problem))
    throw std::invalid_argument("basis seed has " + std::to_string(directions.rows()) +
                                " rows, the problem's interface " + std::to_string(problem.contact.rows()));
  requireFinite(directions, "basis seed");
}

}  // namespace stc
