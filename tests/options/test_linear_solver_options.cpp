// LinearSolverOptions (src/options/linear_solver_options.hpp): the backend keys, the residual
// tolerance an iterative backend stops at, and what a build without PETSc says (the sanitizer and
// fuzzing builds are such builds: scripts/fuzz.sh).
#include <gtest/gtest.h>

#include <string>

#include "stcontact/core/input_error.hpp"
#include "stcontact/options/linear_solver_options.hpp"
#include "stcontact/options/solver_spec.hpp"

TEST(LinearSolverOptions, ThePetscBackendsAreRefusedByNameInABuildWithoutPetsc) {
  for (const auto& [name, backend] : stc::kLinearBackends) {
    stc::LinearSolverOptions o;
    o.backend = backend;
    if (backend == stc::LinearBackend::Cholmod || stc::petscBackendsBuilt()) {
      EXPECT_NO_THROW(o.validate()) << name;
      continue;
    }
    try {
      o.validate();
      ADD_FAILURE() << name << " accepted in a build without PETSc";
    } catch (const stc::InputError& e) {
      EXPECT_NE(std::string(e.what()).find("built without PETSc"), std::string::npos) << e.what();
    }
  }
}

TEST(LinearSolverOptions, TheResidualToleranceFollowsTheStrategysTolerance) {
  stc::LinearSolverOptions o;
  EXPECT_DOUBLE_EQ(o.residualTolerance(1e-6), 1e-10);  // 1e-4 τ
  EXPECT_DOUBLE_EQ(o.residualTolerance(1e-12), 1e-12);  // at least the floor
  o.rtol = 1e-5;
  EXPECT_DOUBLE_EQ(o.residualTolerance(1e-6), 1e-5);  // set by the scene
  stc::SolverSpec spec;
  spec.setTolerance(1e-4);
  EXPECT_DOUBLE_EQ(spec.linearAtTolerance().rtol, 1e-8);
}

TEST(LinearSolverOptions, OutOfRangeValuesAreRefused) {
  stc::LinearSolverOptions o;
  o.rtol = 1.0;
  EXPECT_THROW(o.validate(), stc::InputError);
  o.rtol = -1e-3;
  EXPECT_THROW(o.validate(), stc::InputError);
  o = {};
  o.max_iterations = 0;
  EXPECT_THROW(o.validate(), stc::InputError);
}

TEST(LinearSolverOptions, EveryBackendHasItsName) {
  EXPECT_EQ(stc::nameOf(stc::LinearBackend::Cholmod), "cholmod");
  EXPECT_EQ(stc::nameOf(stc::LinearBackend::Mumps), "mumps");
  EXPECT_EQ(stc::nameOf(stc::LinearBackend::CgGamg), "cg-gamg");
}
