#include "validation/point_contact_3d.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "fixtures/hemisphere_scene.hpp"
#include "fixtures/two_bodies_scene.hpp"

namespace stc::validation {

Scene pointContactScene(const PointContactSetup& setup) {
  const int steps = setup.press_steps + setup.slide_steps + 1;
  Scene scene = test::hemisphereScene(setup.divisions, steps, setup.friction);
  scene.mesh.core = setup.core;
  scene.material.poisson = setup.poisson;
  const double g0 = -(scene.obstacle.point.z() + scene.mesh.radius);
  const double press = -(g0 + kPointIndentation);
  if (setup.slide_steps == 0) {
    scene.dirichlet[0].history = {{0.0}, {0.0}};
    scene.dirichlet[2].history = {{0.0, 1.0}, {0.0, press}};
    return setup.pair ? test::mirroredPair(scene) : scene;
  }
  const double t_press = double(setup.press_steps) / (steps - 1);
  scene.dirichlet[0].history = {{0.0, t_press, 1.0}, {0.0, 0.0, setup.drive}};
  scene.dirichlet[2].history = {{0.0, t_press, 1.0}, {0.0, press, press}};
  return setup.pair ? test::mirroredPair(scene) : scene;
}

std::vector<Eigen::Vector2d> contactXY(const Problem& problem) {
  std::vector<Eigen::Vector2d> xy;
  for (int node : problem.contact.nodes) xy.push_back(std::get<stc::TetMesh>(problem.body).nodes.col(node).head<2>());
  return xy;
}

double coreCellSize(const Scene& scene) { return scene.mesh.core * scene.mesh.radius / scene.mesh.divisions; }

DiscFit discFromMoments(const std::vector<Eigen::Vector2d>& x, const std::vector<double>& w) {
  double m0 = 0.0, m2 = 0.0;
  Eigen::Vector2d m1 = Eigen::Vector2d::Zero();
  for (std::size_t i = 0; i < x.size(); ++i) {
    m0 += w[i];
    m1 += w[i] * x[i];
    m2 += w[i] * x[i].squaredNorm();
  }
  DiscFit fit;
  fit.total = m0;
  if (m0 <= 0.0) return fit;
  fit.centre = m1 / m0;
  fit.radius = std::sqrt(std::max(0.0, 2.5 * (m2 / m0 - fit.centre.squaredNorm())));
  return fit;
}

Resultant3d resultant3d(const Problem& problem, const Eigen::MatrixXd& lambda, int k) {
  const ContactInterface& c = problem.contact;
  Resultant3d r;
  for (int i = 0; i < c.size(); ++i) {
    EXPECT_NEAR(c.tangents(0, 2 * i), 1.0, 1e-12) << "τ_1 = e_x on the flat";
    r.normal += lambda(3 * i, k);
    r.tangential += lambda.block(3 * i + 1, k, 2, 1);
  }
  return r;
}

std::vector<ContactState> contactStates3d(const Problem& problem, const InterfaceHistory& h, int k) {
  const double force = h.lambda.cwiseAbs().maxCoeff(), length = h.v.cwiseAbs().maxCoeff();
  std::vector<ContactState> states;
  for (int i = 0; i < problem.contact.size(); ++i) {
    const auto tangential = [&](int instant) { return Eigen::Vector2d(h.v.block(3 * i + 1, instant, 2, 1)); };
    const Eigen::Vector2d slip = tangential(k) - (k > 0 ? tangential(k - 1) : Eigen::Vector2d::Zero());
    states.push_back(classifyContact(h.lambda(3 * i, k), h.lambda.block(3 * i + 1, k, 2, 1).norm(), slip.norm(),
                                     problem.contact.friction, force, length));
  }
  return states;
}

}  // namespace stc::validation
