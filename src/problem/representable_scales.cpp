#include "stcontact/problem/representable_scales.hpp"

#include <cmath>
#include <sstream>
#include <string>

#include "stcontact/core/input_error.hpp"

namespace stc {
namespace {

double largestMagnitude(const Eigen::Ref<const Eigen::VectorXd>& v) { return v.size() ? v.cwiseAbs().maxCoeff() : 0.0; }

double largestMagnitude(const std::vector<double>& v) {
  return largestMagnitude(Eigen::Map<const Eigen::VectorXd>(v.data(), static_cast<Eigen::Index>(v.size())));
}

double largestEntry(const Eigen::SparseMatrix<double>& K) {
  return largestMagnitude(Eigen::Map<const Eigen::VectorXd>(K.valuePtr(), K.nonZeros()));
}

[[noreturn]] void refuse(const std::string& key, const std::string& what, double value, const std::string& rule) {
  std::ostringstream msg;
  msg << "key '" << key << "': " << what << " is ";
  if (std::isfinite(value)) msg << value << ", " << rule;
  else msg << "not finite";
  msg << ": energies and the error indicator square it, and a double holds magnitudes in [2.2e-308, 1.8e308] only; "
         "state the scene in other units (e.g. MPa and mm instead of Pa and m)";
  throw InputError(msg.str());
}

/// A scale that may be zero but must not exceed kLargestScale (NaN fails too).
void requireBelowLargest(const std::string& key, const std::string& what, double value) {
  if (!(value <= kLargestScale)) refuse(key, what, value, "above 1e150");
}

// The instants, increasing and finite, and the time span within [kSmallestScale, kLargestScale]:
// below it the instants are subnormal numbers whose ratios (the histories' interpolation) have lost
// their digits (time.end = 1e-320 gave a run without contact, exit 0).
void requireIncreasingInstants(const std::vector<double>& times) {
  const double span = times.empty() ? 0.0 : times.back() - times.front();
  if (times.size() > 1 && std::isfinite(span) && !(span >= kSmallestScale && span <= kLargestScale)) {
    std::ostringstream msg;
    msg << "key 'time.end': the time span " << span << " is outside [1e-150, 1e150], where a double keeps the "
        << "ratios of its instants: choose a " << (span < kSmallestScale ? "larger" : "smaller") << " time.end";
    throw InputError(msg.str());
  }
  for (std::size_t k = 0; k < times.size(); ++k)
    if (!std::isfinite(times[k]) || (k > 0 && !(times[k] > times[k - 1]))) {
      std::ostringstream msg;
      msg << "key 'time.end': instant t_" << k << " = " << times[k]
          << (std::isfinite(times[k]) ? " does not follow t_" + std::to_string(k - 1) : " is not finite")
          << " (t_k = time.end · k / (time.steps − 1) in double precision): choose a "
          << (std::isfinite(times[k]) ? "larger" : "smaller") << " time.end";
      throw InputError(msg.str());
    }
}

void requireStiffnessScale(const Eigen::SparseMatrix<double>& K) {
  const double largest = largestEntry(K);
  if (!(largest >= kSmallestScale && largest <= kLargestScale))
    refuse("material.young", "the stiffness matrix's largest entry (∝ young · element size^(d−2))", largest,
           "outside [1e-150, 1e150]");
}

// Dirichlet entries: their displacements and the forces −K_fD e_D u_d(t) they apply; loads: their forces.
void requireLoadScales(const ModelSpec& scene, const Problem& p) {
  for (std::size_t j = 0; j < p.loads.size(); ++j) {
    const SeparatedLoad& load = p.loads[j];
    const bool dirichlet = j < scene.dirichlet.size();
    const std::string key = dirichlet ? "dirichlet[" + std::to_string(j) + "].values"
                                      : "load[" + std::to_string(j - scene.dirichlet.size()) + "].values";
    const double value = largestMagnitude(load.values);
    if (dirichlet) requireBelowLargest(key, "the largest prescribed displacement", value);
    requireBelowLargest(key, dirichlet ? "the force it applies (max |K_fD| · max |u_d|)" : "the largest nodal force",
                        largestMagnitude(load.free_force) * value);
  }
}

// `key`: the obstacle's key that sets the gaps (obstacle.point of a plane, obstacle.centre of a ball).
void requireGapScale(const Problem& p, const std::string& key) {
  const double gap = largestMagnitude(p.contact.initial_gap);
  requireBelowLargest(key, "the largest initial gap", gap);
  requireBelowLargest(key, "the force of the largest initial gap (max |K| · max |g0|)",
                      largestEntry(p.stiffness) * gap);
}

}  // namespace

void requireRepresentableScales(const ModelSpec& scene, const Problem& problem) {
  requireIncreasingInstants(problem.times);
  requireStiffnessScale(problem.stiffness);
  requireLoadScales(scene, problem);
  const bool pair = !scene.contact.master.empty();
  const ObstacleType type = scene.obstacle.type;
  requireGapScale(problem, pair                           ? "contact.master"
                           : type == ObstacleType::Plane    ? "obstacle.point"
                           : type == ObstacleType::Polyline ? "obstacle.points"
                           : type == ObstacleType::Surface  ? "obstacle.file"
                                                            : "obstacle.centre");
}

}  // namespace stc
