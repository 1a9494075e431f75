// A rigid obstacle given as a triangulated surface (src/contact/surface_obstacle.hpp): the closest
// point's regions and signs, a flat triangulation is the plane, the committed spherical cap
// (examples/meshes/sphere_cap.msh) is the sphere within the facets' sagitta, and the Gmsh surface
// reader's refusals.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <filesystem>
#include <sstream>

#include "fixtures/hemisphere_scene.hpp"
#include "stcontact/contact/obstacle.hpp"
#include "stcontact/core/input_error.hpp"
#include "stcontact/incremental/incremental_solver.hpp"
#include "stcontact/io/contact_tables.hpp"
#include "stcontact/mesh/gmsh_reader.hpp"
#include "stcontact/problem/problem.hpp"
#include "stcontact/scene/scene_reader.hpp"

namespace stc {
namespace {

SurfaceObstacle unitTriangle() {
  Eigen::Matrix3Xd nodes(3, 3);
  nodes << 0.0, 1.0, 0.0,  //
      0.0, 0.0, 1.0,       //
      0.0, 0.0, 0.0;
  return makeSurfaceObstacle(nodes, Eigen::Vector3i(0, 1, 2), false);
}

TEST(SurfaceObstacle, InsideATriangleItsNormalAndTheDistanceToItsPlane) {
  const SurfacePoint p = closestSurfacePoint(unitTriangle(), Eigen::Vector3d(0.2, 0.3, 0.5));
  EXPECT_EQ(p.normal, Eigen::Vector3d(0.0, 0.0, 1.0));
  EXPECT_DOUBLE_EQ(p.gap, 0.5);
  EXPECT_DOUBLE_EQ(closestSurfacePoint(unitTriangle(), Eigen::Vector3d(0.2, 0.3, -0.5)).gap, -0.5);
}

// Beyond an edge or a vertex: the unit vector from the closest point, signed by the pseudo-normal.
TEST(SurfaceObstacle, BeyondAnEdgeOrAVertexTheDirectionFromTheClosestPoint) {
  const SurfacePoint edge = closestSurfacePoint(unitTriangle(), Eigen::Vector3d(0.5, -0.5, 0.5));
  EXPECT_NEAR(edge.gap, std::sqrt(0.5), 1e-15);
  EXPECT_TRUE(edge.normal.isApprox(Eigen::Vector3d(0.0, -1.0, 1.0).normalized(), 1e-15));
  const SurfacePoint vertex = closestSurfacePoint(unitTriangle(), Eigen::Vector3d(-1.0, -1.0, -1.0));
  EXPECT_NEAR(vertex.gap, -std::sqrt(3.0), 1e-15);  // below: behind the vertex's pseudo-normal (0, 0, 1)
  EXPECT_TRUE(vertex.normal.isApprox(Eigen::Vector3d(1.0, 1.0, 1.0).normalized(), 1e-15));
  const SurfacePoint flipped = closestSurfacePoint(
      makeSurfaceObstacle(unitTriangle().nodes, Eigen::Vector3i(0, 1, 2), true), Eigen::Vector3d(0.2, 0.3, 0.5));
  EXPECT_DOUBLE_EQ(flipped.gap, -0.5);  // side = "inside": the body below
}

// The plane z = −1.01 as two triangles of a 6 × 6 square: every contact node of the hemisphere has
// the plane's gap and normal to round-off (the nodes over the diagonal x = y take the edge's rule).
TEST(SurfaceObstacle, AFlatTriangulationIsThePlane) {
  Eigen::Matrix3Xd nodes(3, 4);
  nodes << -3.0, 3.0, 3.0, -3.0,  //
      -3.0, -3.0, 3.0, 3.0,       //
      -1.01, -1.01, -1.01, -1.01;
  Eigen::Matrix3Xi triangles(3, 2);
  triangles << 0, 0,  //
      1, 2,           //
      2, 3;
  const Obstacle flat = makeSurfaceObstacle(nodes, triangles, false);
  const Scene scene = test::hemisphereScene(4, 3);
  const Obstacle plane = makeObstacle(scene.obstacle);
  const Problem problem = buildProblem(scene);
  const Eigen::MatrixXd x = problem.nodePositions();
  for (int node : problem.contact.nodes) {
    EXPECT_NEAR(obstacleGap(flat, x.col(node)), obstacleGap(plane, x.col(node)), 1e-15) << node;
    // over the diagonal edge the normal is (x − p)/|x − p|: the plane's to round-off
    EXPECT_LE((obstacleNormal(flat, x.col(node)) - obstacleNormal(plane, x.col(node))).norm(), 1e-13) << node;
  }
}

Scene onSphere(const std::string& file, int divisions) {
  const auto scenes = std::filesystem::path(STC_SOURCE_DIR) / "examples/scenes";
  return readScene(scenes / file, {"mesh.divisions=" + std::to_string(divisions), "time.steps=21"});
}

// The committed cap (triangles of size 0.08 on the sphere of radius 2, their corners on it) against
// the sphere itself: a triangle of circumradius ρ lies within R − √(R² − ρ²) inside the sphere, so
// the gaps differ by at most that over the cap's largest ρ (measured 5.1e-4 against the bound 7.9e-4);
// the pressed hemisphere's vertical force by −0.58 % (146.5 against 147.4, divisions 4), and its whole
// resultant in the global frame (reactions.csv's force_x, force_y, force_z) within 2 % of the sphere's,
// (−21.36, −0.07, 146.45) against (−21.93, 0, 147.23), where the sums of the turning frames' tangential
// components are not: (−7.41, 14.38) against (−16.35, 5.61).
TEST(SurfaceObstacle, ASphericalCapIsTheSphereWithinItsFacetsDepth) {
  const Scene surface = onSphere("on_sphere_surface.toml", 4), sphere = onSphere("hard/on_sphere.toml", 4);
  const SurfaceTriangles cap = readGmshSurface(surface.obstacle.file);
  double rho = 0.0;  // the largest circumradius |a| |b| |a − b| / (2 |a × b|)
  for (Eigen::Index t = 0; t < cap.triangles.cols(); ++t) {
    const Eigen::Vector3d a = cap.nodes.col(cap.triangles(1, t)) - cap.nodes.col(cap.triangles(0, t));
    const Eigen::Vector3d b = cap.nodes.col(cap.triangles(2, t)) - cap.nodes.col(cap.triangles(0, t));
    rho = std::max(rho, a.norm() * b.norm() * (a - b).norm() / (2.0 * a.cross(b).norm()));
  }
  const double depth = 2.0 - std::sqrt(4.0 - rho * rho);
  const Problem a = buildProblem(surface), b = buildProblem(sphere);
  ASSERT_EQ(a.contact.nodes, b.contact.nodes);
  double largest = 0.0;
  for (int i = 0; i < a.contact.size(); ++i) {
    if (b.contact.initial_gap[i] > 0.2) continue;  // far from the cap's edge: the contact zone and beyond
    largest = std::max(largest, std::abs(a.contact.initial_gap[i] - b.contact.initial_gap[i]));
  }
  std::cout << "[ measured ] largest gap difference " << largest << ", the facets' depth " << depth << "\n";
  EXPECT_LE(largest, depth);
  const SolveResult on_surface = solveIncremental(a), on_sphere = solveIncremental(b);
  const int k = a.numSteps() - 1;
  double p_surface = 0.0, p_sphere = 0.0;
  for (int i = 0; i < a.contact.size(); ++i) {
    p_surface += on_surface.interface.lambda(3 * i, k) * a.contact.normals(2, i);
    p_sphere += on_sphere.interface.lambda(3 * i, k) * b.contact.normals(2, i);
  }
  std::cout << "[ measured ] vertical force " << p_surface << " on the cap, " << p_sphere << " on the sphere\n";
  EXPECT_NEAR(p_surface / p_sphere, 1.0, 0.02);
  const Eigen::Vector3d f_surface = reactionTable(a, on_surface).force.col(k);
  const Eigen::Vector3d f_sphere = reactionTable(b, on_sphere).force.col(k);
  std::cout << "[ measured ] resultant " << f_surface.transpose() << " on the cap, " << f_sphere.transpose()
            << " on the sphere\n";
  EXPECT_LE((f_surface - f_sphere).norm(), 0.02 * f_sphere.norm());
  EXPECT_GT(f_sphere.head<2>().norm(), 0.05 * f_sphere.norm());  // a tangential resultant to compare
}

TEST(SurfaceObstacle, TheReaderRefusesAVolumeMesh) {
  const auto error = [](const std::filesystem::path& file) {
    try {
      readGmshSurface(file);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  const auto meshes = std::filesystem::path(STC_SOURCE_DIR) / "examples/meshes";
  EXPECT_NE(error(meshes / "half_ball_graded_small.msh").find("a rigid surface is given by its triangles alone"), std::string::npos);
  EXPECT_EQ(error(meshes / "sphere_cap.msh"), "");
}

}  // namespace
}  // namespace stc
