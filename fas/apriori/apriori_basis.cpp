#include "stcontact/fas/apriori/apriori_basis.hpp"

#include "stcontact/linalg/dense_decompositions.hpp"
#include "stcontact/pgd/separated_history.hpp"

namespace stc::fas {

AprioriBasisProvider::AprioriBasisProvider(pgd::ControlledGlobalStage& stage, AprioriBasisOptions options)
    : stage_(stage), options_(options) {
  options_.validate();
}

CoarseSpace AprioriBasisProvider::coarseSpace(const InterfaceHistory& hat) {
  // The coordinates of ũ, whitened: in them the A-product is the Euclidean one, and modes are unit
  // vectors (anticipation first: it may add directions to the basis and its factor).
  pgd::ControlledGlobalStage::Anticipated next;
  if (options_.anticipate)
    next = stage_.anticipateWhitened(hat, options_.step_samples);
  else
    next.whitened = pgd::whitenedHistory(stage_.basis(), stage_.coordinates());
  const Eigen::MatrixXd& whitened = next.whitened;
  const pgd::ResponseBasis& basis = stage_.basis();
  const pgd::EnergyFactor& factor = basis.energyFactor();
  if (factor.rank() <= options_.modes + options_.increment_modes) {
    // The whole expansion fits: its span is the coarse space (early cycles, and expansions of low
    // rank such as a problem without contact, whose few energy modes alone starve the coarse step).
    previous_ = whitened;
    const Eigen::MatrixXd all = Eigen::MatrixXd::Identity(factor.rank(), factor.rank());
    return CoarseSpace::fromTraces(pgd::modeTraces(basis, factor.combination(all)));
  }
  Eigen::MatrixXd U = pgd::leadingSingularVectors(whitened, options_.modes);
  if (options_.increment_modes > 0 && previous_.size() > 0) {
    // ũ − ũ_previous in Φ̂: R only gains columns, and rows that start at them, so R [G; c_prev; 0] is
    // the previous whitened history with zero rows below (energy_factor.hpp).
    // Beside it the sketched step of the next relaxation, ũ − ũ_last (anticipateWhitened).
    // (Blocks assigned one by one: an empty step is 0 × 0, which Eigen's comma initializer reads as
    // a row of its own and asserts on.)
    Eigen::MatrixXd d(whitened.rows(), whitened.cols() + next.step.cols());
    d.leftCols(whitened.cols()) = whitened;
    if (next.step.cols() > 0) d.rightCols(next.step.cols()) = next.step;
    d.topLeftCorner(previous_.rows(), previous_.cols()) -= previous_;
    d -= U * (U.transpose() * d);
    const Eigen::MatrixXd V = pgd::leadingSingularVectors(d, options_.increment_modes, 1e-10);
    Eigen::MatrixXd all(U.rows(), U.cols() + V.cols());
    all.leftCols(U.cols()) = U;
    all.rightCols(V.cols()) = V;
    U = linalg::orthonormalColumns(all);
  }
  previous_ = whitened;
  return CoarseSpace::fromTraces(pgd::modeTraces(basis, factor.combination(U)));
}

std::unique_ptr<BasisProvider> SeparatedCoarseBasis::providerOn(pgd::ControlledGlobalStage& stage,
                                                                const Problem& problem,
                                                                const AprioriBasisOptions& apriori) const {
  if (make) return make(stage, problem);
  return std::make_unique<AprioriBasisProvider>(stage, apriori);
}

}  // namespace stc::fas
