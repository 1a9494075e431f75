// The files of `stcontact svd` (studies/svd_tables.hpp, studies/svd_figures.hpp): table layouts, the √σ
// scaling of the seed's figure captions, the deformed-mesh data, and the gnuplot run that moves
// finished PNGs into place (skipped where gnuplot is not installed).
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "fixtures/seed_scene.hpp"
#include "stcontact/core/input_error.hpp"
#include "stcontact/incremental/incremental_solver.hpp"
#include "stcontact/io/atomic_file.hpp"
#include "stcontact/linalg/backends/cholmod_factor.hpp"
#include "stcontact/operators/displacement.hpp"
#include "stcontact/studies/svd_figures.hpp"
#include "stcontact/studies/svd_tables.hpp"
#include "studies/text_lines.hpp"

namespace {

using stc::pgd::SpaceTimeSvd;

struct Case {
  stc::Problem problem;
  SpaceTimeSvd svd;
  std::unique_ptr<stc::ModeLocalisation> localisation;
};

// A small seed scene (21 arc nodes, 21 instants), its energy SVD and localisation, built once.
const Case& smallCase() {
  static const Case c = [] {
    Case c{stc::buildProblem(stc::test::seedScene(21, 21)), {}, nullptr};
    const stc::SolveResult solved = stc::solveIncremental(c.problem);
    const stc::CholmodFactor factor(c.problem.stiffness_free, "K_ff");
    const Eigen::MatrixXd U = stc::fullDisplacements(c.problem, factor, solved.interface.lambda);
    c.svd = stc::pgd::energySvd(U, c.problem.stiffness);
    c.localisation = std::make_unique<stc::ModeLocalisation>(
        c.problem, stc::ContactZone::everClosed(c.problem, solved), std::vector<double>{0.1, 0.2});
    return c;
  }();
  return c;
}

using stc::test::lines;

TEST(SvdTables, SingularValuesCsvListsEveryPairWithCumulativeEnergy) {
  const Case& c = smallCase();
  const auto rows = lines(stc::singularValuesCsv(c.svd));
  ASSERT_EQ(rows.size(), static_cast<std::size_t>(c.svd.size() + 1));
  EXPECT_EQ(rows[0], "i,sigma,energy_fraction,cumulative_energy");
  EXPECT_EQ(rows[1].rfind("1,", 0), 0u);
  const double last = std::stod(rows.back().substr(rows.back().rfind(',') + 1));
  EXPECT_NEAR(last, 1.0, 1e-12);
}

TEST(SvdTables, TimeFunctionsAreScaledBySquareRootOfSigma) {
  const Case& c = smallCase();
  const auto rows = lines(stc::timeFunctionsCsv(c.svd, c.problem.times, 3));
  ASSERT_EQ(rows.size(), c.problem.times.size() + 1);
  EXPECT_EQ(rows[0], "t,mode_1,mode_2,mode_3");
  // Last instant, mode 1: ν_1(t_20) √σ_1.
  std::istringstream last(rows.back());
  std::string t, mode1;
  std::getline(last, t, ',');
  std::getline(last, mode1, ',');
  EXPECT_NEAR(std::stod(mode1), c.svd.time(20, 0) * std::sqrt(c.svd.sigma[0]), 1e-10 * std::sqrt(c.svd.sigma[0]));
  EXPECT_THROW(stc::timeFunctionsCsv(c.svd, c.problem.times, c.svd.size() + 1), stc::InputError);
}

TEST(SvdTables, LocalisationCsvHasOneColumnPerBandAndEmptyCellsForUnresolvedModes) {
  const Case& c = smallCase();
  ASSERT_LT(c.svd.resolved, 10);  // the small history has few resolved pairs
  const auto rows = lines(stc::localisationCsv(c.svd, *c.localisation, 10));
  ASSERT_EQ(rows.size(), 11u);
  EXPECT_EQ(rows[0],
            "mode,sigma,energy_fraction,resolved,share_d0.1,share_d0.2,concentration_d0.1,concentration_d0.2,"
            "mean_distance");
  EXPECT_NE(rows[1].find(",1,"), std::string::npos);
  EXPECT_EQ(rows[10].substr(rows[10].size() - 6), "0,,,,,");  // resolved = 0, five empty cells
  for (const auto& row : rows) EXPECT_EQ(std::count(row.begin(), row.end(), ','), 8) << row;
}

TEST(SvdTables, ModesVtuCarriesScaledModesAndEnergyDensities) {
  const Case& c = smallCase();
  const std::string vtu = stc::modesVtu(std::get<stc::TriMesh>(c.problem.body), c.svd, 2, c.localisation.get());
  EXPECT_NE(vtu.find("Name=\"mode_1\""), std::string::npos);
  EXPECT_NE(vtu.find("Name=\"mode_2\""), std::string::npos);
  EXPECT_EQ(vtu.find("Name=\"mode_3\""), std::string::npos);
  EXPECT_NE(vtu.find("Name=\"energy_density_2\""), std::string::npos);
}

TEST(SvdTables, DeformedModesDataHasOneClosedPolygonPerElementAndTheAskedAmplitude) {
  const Case& c = smallCase();
  std::vector<double> scales;
  const std::string data = stc::deformedModesData(std::get<stc::TriMesh>(c.problem.body), c.svd, 2, c.localisation.get(), 0.1, scales);
  ASSERT_EQ(scales.size(), 2u);
  int vertices = 0;
  for (const auto& line : lines(data))
    if (!line.empty() && line[0] != '#') ++vertices;
  EXPECT_EQ(vertices, 2 * 4 * std::get<stc::TriMesh>(c.problem.body).numElements());
  const Eigen::VectorXd u = c.svd.space.col(0) * std::sqrt(c.svd.sigma[0]) * scales[0];
  const Eigen::Map<const Eigen::Matrix2Xd> nodal(u.data(), 2, u.size() / 2);
  EXPECT_NEAR(nodal.colwise().norm().maxCoeff(), 0.1, 1e-12);
}

bool gnuplotInstalled() { return std::system("command -v gnuplot > /dev/null 2>&1") == 0; }

TEST(SvdFigures, GnuplotDrawsEveryPictureAndLeavesNoTemporary) {
  if (!gnuplotInstalled()) GTEST_SKIP() << "gnuplot is not installed";
  const Case& c = smallCase();
  const auto dir = std::filesystem::temp_directory_path() / ("stc_svd_figures_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  stc::SvdFigureSpec spec;
  spec.scene = "small \"seed\"";  // quotes must not break the script
  spec.singular_values = c.svd.size();
  spec.time_functions = 4;
  stc::writeFileAtomically(dir / "singular_values.csv", stc::singularValuesCsv(c.svd));
  stc::writeFileAtomically(dir / "time_functions.csv", stc::timeFunctionsCsv(c.svd, c.problem.times, 4));
  stc::writeFileAtomically(dir / "modes_deformed.dat", stc::deformedModesData(std::get<stc::TriMesh>(c.problem.body), c.svd, 4,
                                                                                   c.localisation.get(), 0.1,
                                                                                   spec.mode_scales));
  for (int i = 0; i < 4; ++i) spec.mode_energy.push_back(c.svd.energyFraction(i));
  stc::writeFileAtomically(dir / "svd_figures.gp", stc::svdFiguresScript(spec));
  std::string detail;
  EXPECT_EQ(stc::drawSvdFigures(dir, detail), stc::FigureStatus::Drawn) << detail;
  for (const auto& name : stc::svdFigureNames()) {
    EXPECT_GT(std::filesystem::file_size(dir / name), 1000u) << name;
    EXPECT_FALSE(std::filesystem::exists(dir / (name + ".tmp"))) << name;
  }
  std::filesystem::remove_all(dir);
}

TEST(SvdFigures, FailingScriptReplacesNoPicture) {
  if (!gnuplotInstalled()) GTEST_SKIP() << "gnuplot is not installed";
  const auto dir = std::filesystem::temp_directory_path() / ("stc_svd_broken_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  stc::writeFileAtomically(dir / "modes.png", "old");
  stc::writeFileAtomically(dir / "svd_figures.gp", "set output 'modes.png'.suffix\nplot 'no_such_file.csv'\n");
  std::string detail;
  EXPECT_EQ(stc::drawSvdFigures(dir, detail), stc::FigureStatus::GnuplotFailed);
  EXPECT_NE(detail.find("exit status"), std::string::npos) << detail;
  std::ifstream in(dir / "modes.png");
  std::string content;
  std::getline(in, content);
  EXPECT_EQ(content, "old");
  EXPECT_FALSE(std::filesystem::exists(dir / "modes.png.tmp"));
  std::filesystem::remove_all(dir);
}

}  // namespace
