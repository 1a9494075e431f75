#pragma once
// The visitor made of lambdas, one per alternative of a std::variant (cppreference, std::visit,
// example 4): std::visit(Overloaded{[](const TriMesh&) {...}, [](const TetMesh&) {...}}, body).
namespace stc {

template <class... Lambdas>
struct Overloaded : Lambdas... {
  using Lambdas::operator()...;
};
/// The deduction guide C++17 needed and clang 14 (the fuzz build's) still does.
template <class... Lambdas>
Overloaded(Lambdas...) -> Overloaded<Lambdas...>;

}  // namespace stc
