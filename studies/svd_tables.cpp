#include "stcontact/studies/svd_tables.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "stcontact/core/input_error.hpp"
#include "stcontact/io/vtu_writer.hpp"

namespace stc {
namespace {

void checkModes(const pgd::SpaceTimeSvd& svd, int modes) {
  if (modes < 1 || modes > svd.size())
    throw InputError("SVD output: " + std::to_string(modes) + " modes asked, " + std::to_string(svd.size()) +
                     " computed");
}

std::ostringstream csvStream() {
  std::ostringstream out;
  out.precision(12);
  return out;
}

// Υ_i √σ_i as a 2 × nodes matrix (dofs interleaved: u_x of node j at 2j, u_y at 2j + 1).
Eigen::MatrixXd scaledMode(const pgd::SpaceTimeSvd& svd, int i) {
  const Eigen::VectorXd u = svd.space.col(i) * std::sqrt(svd.sigma[i]);
  return Eigen::Map<const Eigen::MatrixXd>(u.data(), 2, u.size() / 2);
}

}  // namespace

std::string singularValuesCsv(const pgd::SpaceTimeSvd& svd) {
  auto out = csvStream();
  out << "i,sigma,energy_fraction,cumulative_energy\n";
  for (int i = 0; i < svd.size(); ++i)
    out << i + 1 << ',' << svd.sigma[i] << ',' << svd.energyFraction(i) << ',' << svd.cumulativeEnergy(i) << '\n';
  return out.str();
}

std::string timeFunctionsCsv(const pgd::SpaceTimeSvd& svd, const std::vector<double>& times, int modes) {
  checkModes(svd, modes);
  if (static_cast<Eigen::Index>(times.size()) != svd.time.rows())
    throw InputError("SVD output: " + std::to_string(times.size()) + " instants for time functions of " +
                     std::to_string(svd.time.rows()));
  auto out = csvStream();
  out << 't';
  for (int i = 0; i < modes; ++i) out << ",mode_" << i + 1;
  out << '\n';
  for (std::size_t k = 0; k < times.size(); ++k) {
    out << times[k];
    for (int i = 0; i < modes; ++i) out << ',' << svd.time(static_cast<Eigen::Index>(k), i) * std::sqrt(svd.sigma[i]);
    out << '\n';
  }
  return out.str();
}

std::string localisationCsv(const pgd::SpaceTimeSvd& svd, const ModeLocalisation& localisation, int modes) {
  checkModes(svd, modes);
  const auto& depths = localisation.bandDepths();
  const std::vector<double> area_share = localisation.bandAreaShares();
  auto out = csvStream();
  out << "mode,sigma,energy_fraction,resolved";
  for (double d : depths) out << ",share_d" << d;
  for (double d : depths) out << ",concentration_d" << d;
  out << ",mean_distance\n";
  for (int i = 0; i < modes; ++i) {
    const bool resolved = i < svd.resolved;
    out << i + 1 << ',' << svd.sigma[i] << ',' << svd.energyFraction(i) << ',' << (resolved ? 1 : 0);
    if (!resolved) {
      out << std::string(2 * depths.size() + 1, ',') << '\n';
      continue;
    }
    const LocalisationMeasure m = localisation.measure(svd.space.col(i));
    for (double s : m.band_share) out << ',' << s;
    for (std::size_t j = 0; j < depths.size(); ++j) out << ',' << m.band_share[j] / area_share[j];
    out << ',' << m.mean_distance << '\n';
  }
  return out.str();
}

std::string modesVtu(const TriMesh& mesh, const pgd::SpaceTimeSvd& svd, int modes, const ModeLocalisation* localisation) {
  checkModes(svd, modes);
  std::vector<PointField> points;
  std::vector<CellField> cells;
  for (int i = 0; i < modes; ++i) {
    points.push_back({"mode_" + std::to_string(i + 1), scaledMode(svd, i)});
    if (localisation) {
      const Eigen::VectorXd density = localisation->elementEnergies(svd.space.col(i)).cwiseQuotient(localisation->areas());
      cells.push_back({"energy_density_" + std::to_string(i + 1), density.transpose()});
    }
  }
  return vtuDocument(mesh, points, cells);
}

std::string deformedModesData(const TriMesh& mesh, const pgd::SpaceTimeSvd& svd, int modes,
                              const ModeLocalisation* localisation, double max_displacement,
                              std::vector<double>& scales) {
  checkModes(svd, modes);
  scales.assign(modes, 0.0);
  std::ostringstream out;
  out.precision(7);
  for (int i = 0; i < modes; ++i) {
    const Eigen::MatrixXd u = scaledMode(svd, i);
    const double largest = u.colwise().norm().maxCoeff();
    scales[i] = largest > 0.0 ? max_displacement / largest : 0.0;
    const Eigen::Matrix2Xd x = mesh.nodes + scales[i] * u;
    Eigen::VectorXd colour = Eigen::VectorXd::Ones(mesh.numElements());
    if (localisation && i < svd.resolved) {
      const Eigen::VectorXd energy = localisation->elementEnergies(svd.space.col(i));
      const double mean = energy.sum() / localisation->areas().sum();
      colour = energy.cwiseQuotient(localisation->areas()) / mean;
    }
    out << "# mode " << i + 1 << ", scale " << scales[i] << '\n';
    for (int e = 0; e < mesh.numElements(); ++e) {
      for (int a = 0; a <= 3; ++a) {  // closed: the first vertex again, so that `with lines` draws every edge
        const int node = mesh.triangles(a % 3, e);
        out << x(0, node) << ' ' << x(1, node) << ' ' << std::max(colour[e], 1e-30) << '\n';
      }
      out << '\n';
    }
    out << "\n\n";
  }
  return out.str();
}

}  // namespace stc
