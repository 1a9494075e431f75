#pragma once
// The seed scene (seed_scene.hpp) extruded along z: the half_disc_slab generator, the same obstacle
// and drive, and u_z = 0 on both faces, so that the slab is in plane strain like the 2D seed.
#include "tests/solver/seed_scene.hpp"

namespace stc::test {

inline Scene slabScene(int arc_nodes = 31, int steps = 41, double thickness = 0.05, int layers = 2) {
  Scene scene = seedScene(arc_nodes, steps);
  scene.name = "slab";
  scene.dimension = 3;
  scene.mesh.generator = "half_disc_slab";
  scene.mesh.thickness = thickness;
  scene.mesh.layers = layers;
  scene.obstacle.point = Eigen::Vector3d(0.0, -1.01, 0.0);
  scene.obstacle.normal = Eigen::Vector3d(0.0, 1.0, 0.0);
  scene.dirichlet.push_back({"front", Component::Z, {{0.0}, {0.0}}});
  scene.dirichlet.push_back({"back", Component::Z, {{0.0}, {0.0}}});
  return scene;
}

}  // namespace stc::test
