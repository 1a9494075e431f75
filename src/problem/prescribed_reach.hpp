#pragma once
// What the prescribed motion tells before any solve (docs/method.md §5, "The reduced interface").
// Each [[dirichlet]] history moves its dofs along one axis by the same amount (src/problem/problem.hpp,
// SeparatedLoad), so when the loading is prescribed motion alone it is a translation
// w(t) = Σ_l values_l(t) a_l, a_l the axis of history l (for two bodies, the slave's minus the
// master's). A body that followed it rigidly would bring contact node i to the gap g0_i + n_i · w(t):
//  - the nodes whose gap it closes at some instant are those the contact can reach. Elastic
//    deformation moves the nodes near the contact less than the rigid motion (the body is
//    compressed there), so the set is usually a superset of the contact zone; it is a prediction,
//    and the reduced interface checks the nodes it leaves out (fas/apriori/reduced_interface.hpp);
//  - the interface displacement of that rigid motion is a start for the iteration closer to the
//    solution than s = 0: its first local stage already presses the reached nodes on the obstacle.
#include <Eigen/Core>
#include <optional>
#include <vector>

#include "stcontact/problem/problem.hpp"
#include "stcontact/spacetime/interface_history.hpp"

namespace stc {

/// w(t_k), d × m (column k), when the loading is a prescribed translation alone. None (nullopt) for
/// an applied force (whose reach needs a solve) or a history whose prescribed dofs lie along more
/// than one axis. Histories and forces that are zero at every instant are left out. Two bodies
/// (ContactInterface::isPair): the gaps close by the bodies' relative motion, so w is the slave
/// body's translation minus the master body's (each history moves the dofs of one body, else none).
std::optional<Eigen::MatrixXd> prescribedTranslation(const Problem& problem);

/// The nodes i (increasing) with g0_i + min_k n_i · w(t_k) ≤ margin, w = W's columns.
std::vector<int> nodesWithinReach(const ContactInterface& contact, const Eigen::MatrixXd& W, double margin);

/// The interface history of the body carried rigidly by w: v_n = n_i · w(t_k), v_τ = τ_i · w(t_k)
/// (0 on held rows), λ = 0.
InterfaceHistory rigidMotionHistory(const ContactInterface& contact, const Eigen::MatrixXd& W);
/// Its rows `rows` alone (interface rows, any order), the same values: what a solve on a zone of the
/// interface reads, without the whole interface's history (at 3009 contact nodes and 10⁴ instants,
/// 1.4 GB where the zone of 197 nodes reads 95 MB).
InterfaceHistory rigidMotionHistory(const ContactInterface& contact, const Eigen::MatrixXd& W, const std::vector<int>& rows);

}  // namespace stc
