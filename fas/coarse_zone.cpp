#include "fas/coarse_zone.hpp"

#include <algorithm>

namespace stc::fas {
namespace {

// Sorts node i's d rows into the zone's or the far ones.
void addNode(int d, int i, bool in_zone, CoarseZone& zone) {
  if (in_zone) zone.nodes.push_back(i);
  for (int a = 0; a < d; ++a) (in_zone ? zone.rows : zone.far_rows).push_back(d * i + a);
}

}  // namespace

CoarseZone coarseZone(const ContactInterface& contact, const InterfaceHistory& s, const InterfaceHistory& hat) {
  const Eigen::Index m = hat.v.cols();
  double delta = 0.0;
  for (int i = 0; i < contact.size(); ++i) {
    const int n = contact.normalRow(i);
    delta = std::max(delta, (s.v.row(n) - hat.v.row(n)).cwiseAbs().maxCoeff());
  }
  CoarseZone zone;
  for (int i = 0; i < contact.size(); ++i) {
    const int n = contact.normalRow(i);
    const double g0 = contact.initial_gap[i];
    bool in_zone = false;
    for (Eigen::Index j = 0; j < m && !in_zone; ++j) in_zone = hat.lambda(n, j) > 0.0 || g0 + hat.v(n, j) < delta;
    addNode(contact.dimension, i, in_zone, zone);
  }
  return zone;
}

CoarseZone wholeInterface(const ContactInterface& contact) {
  CoarseZone zone;
  for (int i = 0; i < contact.size(); ++i) addNode(contact.dimension, i, true, zone);
  return zone;
}

}  // namespace stc::fas
