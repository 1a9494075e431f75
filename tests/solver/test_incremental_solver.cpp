#include <gtest/gtest.h>
#include <iostream>
#include "src/solver/incremental_solver.hpp"
#include "src/solver/contact_law_check.hpp"
#include "tests/solver/seed_scene.hpp"
void run(const stc::Scene& sc, const char* name) {
    const auto p = stc::buildProblem(sc);
    auto r = stc::solveIncremental(p);
    auto v = stc::checkContactLaw(p, r.interface);
    std::cout << name << ": " << r.summary.message << " law " << v.max() << "\n";
}
TEST(Scratch, Run) {
  auto sc = stc::test::seedScene(101, 201);
  run(sc, "seed");
  sc.contact.friction = 0.6; run(sc, "mu0.6");
  sc.contact.friction = 0.0; run(sc, "mu0");
  auto cyc = stc::test::seedScene(101, 201);
  cyc.contact.friction = 0.3;
  cyc.dirichlet[0].history = {{0.0, 0.2, 0.4, 0.6, 0.8, 1.0}, {0.0, 0.0, 0.02, -0.02, 0.02, -0.02}};
  run(cyc, "cyclic mu0.3");
  auto big = stc::test::seedScene(401, 201); run(big, "arc401");
}
