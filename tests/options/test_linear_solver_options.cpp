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
    const bool embedded = backend == stc::LinearBackend::Auto || backend == stc::LinearBackend::Cholmod;
    if (embedded || stc::petscBackendsBuilt()) {
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
  spec.linear.rtol = 1e-9;  // tighter: kept
  EXPECT_DOUBLE_EQ(spec.linearAtTolerance().rtol, 1e-9);
}

// A looser linear solve than 1e-4 τ can make "converged" wrong (docs/method.md §2): refused by name.
TEST(LinearSolverOptions, AResidualToleranceLooserThanTheStrategysIsRefused) {
  stc::SolverSpec spec;
  spec.setTolerance(1e-6);
  spec.linear.rtol = 1e-5;
  try {
    spec.linearAtTolerance();
    ADD_FAILURE() << "linear_rtol = 1e-5 accepted at tolerance 1e-6";
  } catch (const stc::InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "solver option linear_rtol = 1e-05: must be 0 (the default, 1e-10) or at most 1e-4 x solver.tolerance = "
              "1e-10: a looser linear solve can make \"converged\" wrong");
  }
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

TEST(LinearSolverOptions, EveryBackendHasItsNameAndAutoIsTheDefault) {
  EXPECT_EQ(stc::LinearSolverOptions{}.backend, stc::LinearBackend::Auto);
  EXPECT_EQ(stc::nameOf(stc::LinearBackend::Auto), "auto");
  EXPECT_EQ(stc::nameOf(stc::LinearBackend::Cholmod), "cholmod");
  EXPECT_EQ(stc::nameOf(stc::LinearBackend::Mumps), "mumps");
  EXPECT_EQ(stc::nameOf(stc::LinearBackend::CgGamg), "cg-gamg");
}
