#pragma once
// The rigid motions a scene's Dirichlet conditions leave free (docs/method.md §1). A body whose
// prescribed dofs do not hold every rigid motion has a singular K_ff: its equilibrium is not unique
// (contact is one-sided and cannot hold a motion, friction only resists it), and a solver either
// fails ("K_ff is not positive definite") or returns one of infinitely many answers. The rigid
// motions of a body in d dimensions are the d translations and the d(d − 1)/2 rotations about its
// centroid, r(x) = a + ω × (x − x̄); one is free when it moves no prescribed dof. With R the n × r
// matrix of the motions' nodal values (rotations scaled by 1/R_body, so that every column has unit
// size at the body's scale) and R_p its rows of prescribed dofs, the free motions are the null
// space of R_p: its right singular vectors of singular value below 1e-8 of the largest possible (√n_p).
#include <string>
#include <vector>

#include "stcontact/mesh/body_mesh.hpp"

namespace stc {

/// The free rigid motions of `body` given, per dof, whether it is prescribed; each described by its
/// largest parts ("translation along x", "rotation about z", "translation along x with rotation
/// about z"). Empty when the conditions hold the body. A mesh of several connected parts (two
/// bodies) is checked part by part: one entry per part with free motions, "body k of N, around
/// (x̄): translation along x, rotation about z".
std::vector<std::string> freeRigidMotions(const BodyMesh& body, const std::vector<char>& prescribed);

}  // namespace stc
