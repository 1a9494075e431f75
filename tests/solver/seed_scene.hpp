#pragma once
// The seed scene of docs/method.md §6 built in C++, for tests that need a Problem without a scene file:
// half-disc of radius 1 on a rigid plane 0.01 below it, E = 3000, ν = 0.3, μ = 0.15, plane strain,
// the top edge driven down by 0.01 until t = 0.2 (first contact), then down by 0.1 more and sideways
// by 0.05 until t = 1. Smaller variants (arc_nodes 31, steps 41) keep tests fast; the drive is a
// function of t, so t = 0.2 is instant k = (steps − 1)/5.
#include "src/scene/scene.hpp"

namespace stc::test {

inline Scene seedScene(int arc_nodes = 101, int steps = 201) {
  Scene scene;
  scene.name = "seed";
  scene.plane = PlaneModel::Strain;
  scene.mesh.generator = "half_disc";
  scene.mesh.radius = 1.0;
  scene.mesh.arc_nodes = arc_nodes;
  scene.material = {3000.0, 0.3};
  scene.obstacle.type = ObstacleType::Plane;
  scene.obstacle.point = Eigen::Vector2d(0.0, -1.01);
  scene.obstacle.normal = Eigen::Vector2d(0.0, 1.0);
  scene.contact.boundary = "arc";
  scene.contact.friction = 0.15;
  scene.time.steps = steps;
  scene.time.end = 1.0;
  scene.dirichlet.push_back({"top", Component::X, {{0.0, 0.2, 1.0}, {0.0, 0.0, 0.05}}});
  scene.dirichlet.push_back({"top", Component::Y, {{0.0, 0.2, 1.0}, {0.0, -0.01, -0.11}}});
  scene.solver.name = "incremental";
  scene.output.vtu = false;
  return scene;
}

}  // namespace stc::test
