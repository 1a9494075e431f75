#include "validation/validation_support.hpp"

#include <algorithm>
#include <cmath>

#include "fixtures/seed_scene.hpp"
#include "stcontact/incremental/incremental_solver.hpp"
#include "stcontact/latin/latin_solver.hpp"

namespace stc::validation {

const SeedSolutions& seedSolutions() {
  static const std::unique_ptr<SeedSolutions> solved = [] {
    Scene scene = test::seedScene(101, 201);
    scene.search_direction.scale = kSeedSearchScale;
    auto s = std::make_unique<SeedSolutions>();
    s->problem = buildProblem(scene);
    s->incremental = solveIncremental(s->problem);
    latin::LatinOptions options;
    options.stop.tolerance = kSeedLatinTolerance;
    s->latin = latin::solveLatin(s->problem, options);
    s->stiffness_free = std::make_unique<CholmodFactor>(s->problem.stiffness_free, "K_ff");
    return s;
  }();
  return *solved;
}

Resultant resultant(const Eigen::MatrixXd& lambda, int k) {
  Resultant r;
  for (int i = 0; i < lambda.rows() / 2; ++i) {
    r.normal += lambda(2 * i, k);
    r.tangential += lambda(2 * i + 1, k);
  }
  return r;
}

std::vector<double> contactX(const Problem& problem) {
  std::vector<double> x;
  for (int id : problem.contact.nodes) x.push_back(std::get<stc::TriMesh>(problem.body).nodes(0, id));
  return x;
}

double slipIncrement(const InterfaceHistory& h, int i, int k) {
  return h.v(2 * i + 1, k) - (k > 0 ? h.v(2 * i + 1, k - 1) : 0.0);
}

std::vector<ContactState> contactStates(const Problem& problem, const InterfaceHistory& h, int k) {
  const double force = h.lambda.cwiseAbs().maxCoeff(), length = h.v.cwiseAbs().maxCoeff();
  std::vector<ContactState> states;
  for (int i = 0; i < problem.contact.size(); ++i)
    states.push_back(classifyContact(h.lambda(2 * i, k), h.lambda(2 * i + 1, k), slipIncrement(h, i, k),
                                     problem.contact.friction, force, length));
  return states;
}

SemicircleFit semicircleFromMoments(const std::vector<double>& x, const std::vector<double>& w, double h) {
  double m0 = 0.0, m1 = 0.0, m2 = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    m0 += w[i];
    m1 += w[i] * x[i];
    m2 += w[i] * x[i] * x[i];
  }
  SemicircleFit fit;
  fit.total = m0;
  if (m0 <= 0.0) return fit;
  fit.centre = m1 / m0;
  fit.half_width = 2.0 * std::sqrt(std::max(0.0, m2 / m0 - fit.centre * fit.centre - h * h / 6.0));
  return fit;
}

std::vector<double> normalForces(const Eigen::MatrixXd& lambda, int k) {
  std::vector<double> w;
  for (int i = 0; i < lambda.rows() / 2; ++i) w.push_back(lambda(2 * i, k));
  return w;
}

}  // namespace stc::validation
