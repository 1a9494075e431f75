#include "stcontact/mesh/half_disc.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "stcontact/core/input_error.hpp"

namespace stc {
namespace {

using std::numbers::pi;

struct Ring {
  double radius;
  std::vector<int> ids;  // node ids at angles π + π·i/segments, i = 0..segments
};

class HalfDiscBuilder {
 public:
  Ring addRing(double radius, int segments) {
    Ring ring{radius, {}};
    for (int i = 0; i <= segments; ++i) {
      const double angle = pi + pi * i / segments;
      ring.ids.push_back(addNode(radius * std::cos(angle), i == 0 || i == segments ? 0.0
                                                                                   : radius * std::sin(angle)));
    }
    return ring;
  }

  int addNode(double x, double y) {
    points_.push_back({x, y});
    return static_cast<int>(points_.size()) - 1;
  }

  // Zipper between two rings: advance along whichever ring's next node has the smaller angle.
  void zip(const Ring& outer, const Ring& inner) {
    const int n = static_cast<int>(outer.ids.size()) - 1, m = static_cast<int>(inner.ids.size()) - 1;
    int i = 0, j = 0;
    while (i < n || j < m) {
      const bool advance_outer = j == m || (i < n && double(i + 1) / n <= double(j + 1) / m);
      if (advance_outer) {
        addTriangle(outer.ids[i], outer.ids[i + 1], inner.ids[j]);
        ++i;
      } else {
        addTriangle(outer.ids[i], inner.ids[j + 1], inner.ids[j]);
        ++j;
      }
    }
  }

  void fan(const Ring& ring, int centre) {
    for (std::size_t i = 0; i + 1 < ring.ids.size(); ++i) addTriangle(ring.ids[i], ring.ids[i + 1], centre);
  }

  // Stores the triangle counter-clockwise whatever order it is given in.
  void addTriangle(int a, int b, int c) {
    const auto& pa = points_[a];
    const auto& pb = points_[b];
    const auto& pc = points_[c];
    const double area2 = (pb[0] - pa[0]) * (pc[1] - pa[1]) - (pc[0] - pa[0]) * (pb[1] - pa[1]);
    triangles_.push_back(area2 > 0 ? std::array<int, 3>{a, b, c} : std::array<int, 3>{a, c, b});
  }

  TriMesh finish() const {
    TriMesh mesh;
    mesh.nodes.resize(2, static_cast<Eigen::Index>(points_.size()));
    for (std::size_t i = 0; i < points_.size(); ++i) mesh.nodes.col(i) << points_[i][0], points_[i][1];
    mesh.triangles.resize(3, static_cast<Eigen::Index>(triangles_.size()));
    for (std::size_t e = 0; e < triangles_.size(); ++e)
      mesh.triangles.col(e) << triangles_[e][0], triangles_[e][1], triangles_[e][2];
    return mesh;
  }

  const std::vector<std::array<double, 2>>& points() const { return points_; }

 private:
  std::vector<std::array<double, 2>> points_;
  std::vector<std::array<int, 3>> triangles_;
};

BoundaryGroup chain(std::vector<int> ids) {
  BoundaryGroup group;
  for (std::size_t i = 0; i + 1 < ids.size(); ++i) group.edges.push_back({ids[i], ids[i + 1]});
  return group;
}

}  // namespace

void HalfDiscOptions::validate() const {
  if (!(radius > 0.0) || !std::isfinite(radius))
    throw InputError("half_disc: radius = " + std::to_string(radius) + " must be > 0");
  if (arc_nodes < 3) throw InputError("half_disc: arc_nodes = " + std::to_string(arc_nodes) + " must be >= 3");
  if (!(grading >= 1.0) || !(grading <= 4.0))
    throw InputError("half_disc: grading = " + std::to_string(grading) + " must be in [1, 4]");
  const double nodes = halfDiscNodeCount(*this);
  if (nodes * 2 > std::numeric_limits<int>::max())
    throw InputError("half_disc: arc_nodes = " + std::to_string(arc_nodes) + " with grading " + std::to_string(grading) +
                     " would make " + std::to_string(nodes) + " nodes, more than the dof numbering holds");
}

double halfDiscNodeCount(const HalfDiscOptions& options) {
  double segments = options.arc_nodes + 1.0;
  double h = options.radius * pi / segments, radius = options.radius;
  double nodes = segments + 2.0;  // the arc's ring and the centre
  for (;;) {  // makeHalfDisc's rings, as it builds them
    const double h_next = h * options.grading;
    const double r_next = radius - 0.5 * std::sqrt(3.0) * 0.5 * (h + h_next);
    const double m_next = std::round(pi * r_next / h_next);
    if (r_next < 1.2 * h_next || m_next < 4 || nodes > 1e12) break;
    segments = std::min(m_next, segments);
    nodes += segments + 1.0;
    radius = r_next;
    h = h_next;
  }
  return nodes;
}

TriMesh makeHalfDisc(const HalfDiscOptions& options) {
  options.validate();
  HalfDiscBuilder builder;
  int segments = options.arc_nodes + 1;
  double h = options.radius * pi / segments;
  Ring ring = builder.addRing(options.radius, segments);
  const Ring arc = ring;
  std::vector<int> top{ring.ids.front(), ring.ids.back()};
  for (;;) {
    const double h_next = h * options.grading;
    const double r_next = ring.radius - 0.5 * std::sqrt(3.0) * 0.5 * (h + h_next);
    const int m_next = static_cast<int>(std::lround(pi * r_next / h_next));
    if (r_next < 1.2 * h_next || m_next < 4) break;  // close with a fan of at most ~6 triangles
    Ring inner = builder.addRing(r_next, std::min(m_next, segments));
    builder.zip(ring, inner);
    top.push_back(inner.ids.front());
    top.push_back(inner.ids.back());
    ring = inner;
    segments = static_cast<int>(ring.ids.size()) - 1;
    h = h_next;
  }
  const int centre = builder.addNode(0.0, 0.0);
  builder.fan(ring, centre);
  top.push_back(centre);
  std::sort(top.begin(), top.end(), [&](int a, int b) { return builder.points()[a][0] < builder.points()[b][0]; });

  TriMesh mesh = builder.finish();
  mesh.groups["arc"] = chain(arc.ids);
  mesh.groups["top"] = chain(top);
  mesh.finalizeGroups();
  mesh.validate();
  return mesh;
}

}  // namespace stc
