#pragma once
// The 3D seed scene (examples/scenes/hemisphere.toml) built in C++: half-ball of radius 1 on a rigid
// plane 0.01 below its pole, E = 3000, ν = 0.3, the flat top driven down by 0.01 until t = 0.2
// (first contact), then down by 0.1 more and along x by 0.05 until t = 1; u_y = 0 on the top.
// Small variants (divisions 3 or 4, a few tens of instants) keep tests fast.
#include "src/scene/scene.hpp"

namespace stc::test {

inline Scene hemisphereScene(int divisions = 4, int steps = 21, double friction = 0.15) {
  Scene scene;
  scene.name = "hemisphere";
  scene.dimension = 3;
  scene.mesh.generator = "half_ball";
  scene.mesh.radius = 1.0;
  scene.mesh.divisions = divisions;
  scene.mesh.grading = 1.5;
  scene.material = {3000.0, 0.3};
  scene.obstacle.type = ObstacleType::Plane;
  scene.obstacle.point = Eigen::Vector3d(0.0, 0.0, -1.01);
  scene.obstacle.normal = Eigen::Vector3d(0.0, 0.0, 1.0);
  scene.contact.boundary = "contact";
  scene.contact.friction = friction;
  scene.time.steps = steps;
  scene.time.end = 1.0;
  scene.dirichlet.push_back({"top", Component::X, {{0.0, 0.2, 1.0}, {0.0, 0.0, 0.05}}});
  scene.dirichlet.push_back({"top", Component::Y, {{0.0}, {0.0}}});
  scene.dirichlet.push_back({"top", Component::Z, {{0.0, 0.2, 1.0}, {0.0, -0.01, -0.11}}});
  scene.solver.name = "incremental";
  scene.output.vtu = false;
  return scene;
}

}  // namespace stc::test
