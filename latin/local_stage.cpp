#include "stcontact/latin/local_stage.hpp"

#include <algorithm>
#include <array>

#include "stcontact/core/threads.hpp"

namespace stc::latin {
namespace {

// Nodes marched together through the instants. Columns are d n_C rows apart (an instant per
// column): a node marched alone touches a cache line per column, each on a new page at large n_C
// (3202 rows: 25.6 kB apart), and its neighbours come back for the same lines later. Four 2D nodes
// share a line. Each node's arithmetic is the same in any block: the result does not depend on it.
// Measured (docs/threads.md, "The local stage by blocks of nodes"): 4 and 16 alike on 401 × 2001,
// 16 slower than 4 on 401 × 201.
constexpr int kNodeBlock = 4;

template <int D>
using Tangential = Eigen::Matrix<double, D - 1, 1>;
template <int D>
using NodeVector = Eigen::Matrix<double, D, 1>;

// One node's values at one instant: (v, λ) or (v̂, λ̂), normal component first.
template <int D>
struct NodeState {
  NodeVector<D> v, lambda;
};

// P_b(x) on the tangent plane: x when |x| ≤ b, else b x/|x| (in 2D the clamp to [−b, b]).
Eigen::Vector2d projectOnDisc(const Eigen::Vector2d& x, double b) {
  const double norm = x.norm();
  return norm <= b ? x : Eigen::Vector2d(b / norm * x);
}

// A node's constants: its search directions (normal, tangential) and initial gap.
struct NodeConstants {
  double kn = 0.0, kt = 0.0, g0 = 0.0;
};

// The contact law at one node and instant (the formulas of local_stage.hpp): ŝ from s;
// `previous_vt` is v̂_t at the node's previous instant, and becomes this instant's. Inlined into
// the marches.
template <int D>
[[gnu::always_inline]] inline NodeState<D> nodeLaw(const NodeConstants& node, double mu, const NodeState<D>& s,
                                                   Tangential<D>& previous_vt) {
  constexpr int T = D - 1;
  const double kn = node.kn, kt = node.kt, g0 = node.g0;
  const double vn = s.v[0], ln = s.lambda[0];
  const Tangential<D> vt = s.v.template tail<T>(), lt = s.lambda.template tail<T>();
  const double ln_hat = std::max(0.0, ln - kn * (g0 + vn));
  const Tangential<D> c = vt - lt / kt;  // v̂_t that leaves λ̂_t = 0
  NodeState<D> hat;
  Tangential<D> vt_hat;
  if (ln_hat == 0.0) {
    hat.v[0] = vn - ln / kn;
    vt_hat = c;
  } else {
    hat.v[0] = -g0;
    if constexpr (T == 1) {
      const double b = mu * ln_hat / kt;
      vt_hat[0] = std::clamp(previous_vt[0], c[0] - b, c[0] + b);
    } else {
      vt_hat = c + projectOnDisc(previous_vt - c, mu * ln_hat / kt);
    }
  }
  hat.v.template tail<T>() = vt_hat;
  hat.lambda[0] = ln_hat;
  hat.lambda.template tail<T>() = lt + kt * (vt_hat - vt);
  previous_vt = vt_hat;
  return hat;
}

// Nodes first … last − 1 of a D-dimensional interface, kNodeBlock at a time through the m
// instants: `in(i, k)` gives s at node i and instant k, `out(i, k, ŝ)` takes the result.
template <int D, class In, class Out>
void marchNodes(const ContactInterface& contact, int m, int first, int last, In in, Out out) {
  std::array<NodeConstants, kNodeBlock> nodes;
  std::array<Tangential<D>, kNodeBlock> previous_vt;
  for (int begin = first; begin < last; begin += kNodeBlock) {
    const int count = std::min(last - begin, kNodeBlock);
    const Eigen::VectorXd& directions = contact.search_direction;
    for (int j = 0; j < count; ++j) {
      const int i = begin + j;
      nodes[j] = {directions[D * i], directions[D * i + 1], contact.initial_gap[i]};
      previous_vt[j].setZero();
    }
    for (int instant = 0; instant < m; ++instant)
      for (int j = 0; j < count; ++j)
        out(begin + j, instant, nodeLaw<D>(nodes[j], contact.friction, in(begin + j, instant), previous_vt[j]));
  }
}

// ŝ of one node at rows row … row + D − 1 of instant k, component by component (a vector store
// of the two components of λ̂, assembled on the stack, stalled the march: store forwarding).
template <int D>
[[gnu::always_inline]] inline void store(const NodeState<D>& h, int row, int k, InterfaceHistory& hat) {
  for (int d = 0; d < D; ++d) {
    hat.v(row + d, k) = h.v[d];
    hat.lambda(row + d, k) = h.lambda[d];
  }
}

// Nodes split into contiguous ranges, one per thread (the rows of neighbouring nodes share cache
// lines), each range marched by `march<D>(first, last)`.
template <class March>
void overNodeRanges(const ContactInterface& contact, const March& march) {
  parallelRanges(contact.size(), threadCount(), [&](int first, int last) {
    if (contact.dimension == 3) march.template operator()<3>(first, last);
    else march.template operator()<2>(first, last);
  });
}

}  // namespace

void localStage(const ContactInterface& contact, const InterfaceHistory& s, InterfaceHistory& hat) {
  const int m = s.numSteps();
  hat.v.resize(contact.rows(), m);
  hat.lambda.resize(contact.rows(), m);
  overNodeRanges(contact, [&]<int D>(int first, int last) {
    marchNodes<D>(
        contact, m, first, last,
        [&](int i, int k) {
          return NodeState<D>{s.v.template block<D, 1>(D * i, k), s.lambda.template block<D, 1>(D * i, k)};
        },
        [&](int i, int k, const NodeState<D>& h) { store(h, D * i, k, hat); });
  });
}

void localStageOfTrial(const ContactInterface& contact, const Eigen::MatrixXd& v0, const Eigen::MatrixXd& dv,
                       const Eigen::MatrixXd& w, InterfaceHistory* hat, Eigen::MatrixXd* image) {
  const int m = static_cast<int>(w.cols());
  const Eigen::VectorXd& k = contact.search_direction;
  if (hat) {
    hat->v.resize(contact.rows(), m);
    hat->lambda.resize(contact.rows(), m);
  }
  if (image) image->resize(contact.rows(), m);
  overNodeRanges(contact, [&]<int D>(int first, int last) {
    marchNodes<D>(
        contact, m, first, last,
        [&](int i, int j) {
          const auto kd = k.template segment<D>(D * i);
          const NodeVector<D> v = v0.template block<D, 1>(D * i, j) + dv.template block<D, 1>(D * i, j);
          return NodeState<D>{v, w.template block<D, 1>(D * i, j) - kd.cwiseProduct(v)};
        },
        [&](int i, int j, const NodeState<D>& h) {
          if (image)
            for (int d = 0; d < D; ++d) (*image)(D * i + d, j) = h.lambda[d] + k[D * i + d] * h.v[d];
          if (hat) store(h, D * i, j, *hat);
        });
  });
}

}  // namespace stc::latin
