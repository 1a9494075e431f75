#pragma once
// The visitor made of lambdas, one per alternative of a std::variant (cppreference, std::visit,
// example 4): std::visit(Overloaded{[](const TriMesh&) {...}, [](const TetMesh&) {...}}, body).
namespace stc {

template <class... Lambdas>
struct Overloaded : Lambdas... {
  using Lambdas::operator()...;
};

}  // namespace stc
