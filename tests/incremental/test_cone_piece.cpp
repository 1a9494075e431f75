// The cone law at one node (src/incremental/cone_piece.hpp), which both forms of the incremental
// solver evaluate: each piece where its inequality says, its residual zero exactly on the law's
// solutions (Signorini and Coulomb) and nonzero off them, for any ρ > 0.
#include <gtest/gtest.h>

#include <cmath>

#include "stcontact/incremental/cone_piece.hpp"

namespace {

using stc::ContactState;
using stc::Tangent;
using stc::conePiece;

constexpr double kMu = 0.3;

Tangent tangent(double a, double b) {
  Tangent t(2);
  t << a, b;
  return t;
}

}  // namespace

TEST(ConePiece, AnOpenGapWithoutForceIsASolution) {
  for (double rho : {1e-3, 1.0, 1e4}) {
    const stc::ConePiece p = conePiece(0.0, tangent(0.0, 0.0), 0.02, tangent(0.1, -0.2), rho, rho, kMu);
    EXPECT_EQ(p.state, ContactState::Open);
    EXPECT_EQ(p.F_n, 0.0);
    EXPECT_EQ(p.F_t.norm(), 0.0);
  }
  // A force on an open node is its residual: F = λ.
  const stc::ConePiece loaded = conePiece(-1.0, tangent(0.5, 0.25), 0.02, tangent(0.0, 0.0), 1.0, 1.0, kMu);
  EXPECT_EQ(loaded.state, ContactState::Open);
  EXPECT_EQ(loaded.F_n, -1.0);
  EXPECT_EQ(loaded.F_t, tangent(0.5, 0.25));
}

TEST(ConePiece, AClosedNodeInsideTheConeSticks) {
  // g = 0, λ_n = 2, |λ_t| = 0.5 < μ λ_n = 0.6, s = 0: a solution, stuck.
  for (double rho : {1e-3, 1.0, 1e4}) {
    const stc::ConePiece p = conePiece(2.0, tangent(0.3, 0.4), 0.0, tangent(0.0, 0.0), rho, rho, kMu);
    EXPECT_EQ(p.state, ContactState::Stick);
    EXPECT_EQ(p.F_n, 0.0);
    EXPECT_EQ(p.F_t.norm(), 0.0);
  }
  // Penetration and a slip increment inside the cone are the residual: F_n = ρ_n g, F_t = ρ_t s.
  const stc::ConePiece p = conePiece(2.0, tangent(0.3, 0.4), -1e-3, tangent(1e-4, 0.0), 10.0, 5.0, kMu);
  EXPECT_EQ(p.state, ContactState::Stick);
  EXPECT_DOUBLE_EQ(p.F_n, -1e-2);
  EXPECT_DOUBLE_EQ(p.F_t[0], 5e-4);
  EXPECT_EQ(p.F_t[1], 0.0);
}

TEST(ConePiece, ANodeOnTheConeSlidingAgainstItsForceSlips) {
  // g = 0, λ_n = 2, λ_t = μ λ_n along (0.6, 0.8), slipping by s opposite to λ_t: a solution.
  const Tangent direction = tangent(0.6, 0.8), force = kMu * 2.0 * direction;
  for (double rho : {1e-3, 1.0, 1e4}) {
    const stc::ConePiece p = conePiece(2.0, force, 0.0, -0.01 * direction, rho, rho, kMu);
    EXPECT_EQ(p.state, ContactState::Slip);
    EXPECT_NEAR(p.F_t.norm(), 0.0, 1e-15);  // forces of order 1: a few roundings
    EXPECT_NEAR((p.unit - direction).norm(), 0.0, 1e-15);  // ξ̂ = λ_t / |λ_t|
    // q = μ λ̂_n / |ξ| = μ λ_n / (μ λ_n + 0.01 ρ): the Newton step's weight.
    EXPECT_NEAR(p.q, kMu * 2.0 / (kMu * 2.0 + 0.01 * rho), 1e-15);
  }
  // Sliding along its force is not: ξ falls inside the cone, and the residual is the slip, ρ_t s.
  const stc::ConePiece wrong = conePiece(2.0, force, 0.0, 0.01 * direction, 1.0, 1.0, kMu);
  EXPECT_EQ(wrong.state, ContactState::Stick);
  EXPECT_GT(wrong.F_t.norm(), 0.0);
}

TEST(ConePiece, TakesOneTangentInTheDimensionTwo) {
  Tangent t(1), s(1);
  t << -0.6;
  s << 0.05;
  const stc::ConePiece p = conePiece(2.0, t, 0.0, s, 1.0, 1.0, kMu);  // |λ_t| = μ λ_n, s against it
  EXPECT_EQ(p.state, ContactState::Slip);
  EXPECT_EQ(p.unit.size(), 1);
  EXPECT_DOUBLE_EQ(p.unit[0], -1.0);
  EXPECT_NEAR(p.F_t[0], 0.0, 1e-15);
}
