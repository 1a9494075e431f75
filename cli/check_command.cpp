// stcontact check SCENE: validate and print the model's sizes.
#include <iostream>
#include <sstream>
#include <string>
#include <string_view>

#include "stcontact/cli/commands.hpp"
#include "stcontact/io/frame_fields.hpp"
#include "stcontact/io/run_writer.hpp"
#include "stcontact/problem/problem.hpp"
#include "stcontact/scene/scene_reader.hpp"

namespace stc::cli {
namespace {

// "; master body E = 9000, nu = 0.25" for two bodies of two materials, else nothing.
std::string masterMaterial(const Problem& p) {
  if (!p.master_material) return {};
  std::ostringstream text;
  text << "; master body E = " << p.master_material->young << ", nu = " << p.master_material->poisson;
  return text.str();
}

// The search direction's law as `check` prints it (docs/method.md §2).
std::string_view searchLawFormula(SearchLaw law) {
  return law == SearchLaw::Local ? "k = kappa E l_i hbar / (L h_i) (law local, hbar = sum l / sum (l / h))"
                                 : "k = kappa E l_i / L (law tributary)";
}

// What `solve` writes beside the small tables: the frames (their format, instants and count) and
// whether contact.csv is written (docs/interface.md, "Output files of solve").
std::string outputsLine(const OutputSpec& output, const Problem& p) {
  std::ostringstream line;
  line << "solution.h5";
  if (output.frames) {
    const int stride = frameStride(p, output.frame_stride);
    const std::size_t frames = frameSteps(p.numSteps(), stride).size();
    line << (output.format == OutputFormat::Hdf5 ? " + solution.xdmf" : ", solution.pvd + vtu/") << ", " << frames
         << " frames (" << (stride == 1 ? std::string("every instant") : "one in " + std::to_string(stride) + " instants")
         << (output.frame_stride == 0 ? ", output.frame_stride auto" : "") << ")";
  } else {
    line << ", no frames";
  }
  line << (writesContactCsv(p, output) ? ", contact.csv" : ", no contact.csv (output.contact_csv)");
  return line.str();
}

}  // namespace

CLI::App* addCheckCommand(CLI::App& app, CheckArgs& args) {
  auto* cmd = app.add_subcommand("check", "validate a scene and print the model's sizes");
  cmd->add_option("scene", args.scene, "scene file (TOML)")->required();
  cmd->add_option("--set", args.overrides, "override a scene value: section.key=value")->take_all();
  return cmd;
}

int runCheck(const CheckArgs& args) {
  const Scene scene = readScene(args.scene, args.overrides);
  const Problem p = buildProblem(scene);
  const auto& c = p.contact;
  std::cout << "scene            " << scene.name << " (" << args.scene << ")\n"
            << "model            "
            << (p.dimension == 3 ? "3D, P1 tetrahedra" : p.plane == PlaneModel::Strain ? "plane strain" : "plane stress")
            << ", E = " << p.material.young << ", nu = " << p.material.poisson << masterMaterial(p)
            << ", mu = " << c.friction << "\n"
            << "nodes            " << p.numNodes() << "\n"
            << "elements         " << p.numElements() << "\n"
            << "dofs             " << p.numDofs() << " (" << p.numFreeDofs() << " free, "
            << p.numDofs() - p.numFreeDofs() << " prescribed)\n"
            << "contact nodes    " << c.size() << " on boundary '" << scene.contact.boundary << "'"
            << (c.isPair() ? ", node to node with '" + scene.contact.master + "' (two bodies)" : std::string()) << " ("
            << c.rows() << " interface unknowns per field and instant)\n"
            << "steps            " << p.numSteps() << " instants on [" << p.times.front() << ", " << p.times.back()
            << "]\n"
            << (p.frame_motion.size() > 0 ? "obstacle motion  a rigid translation up to |d| = " +
                                                 std::to_string(p.frame_motion.colwise().norm().maxCoeff()) +
                                                 " (solved in the obstacle's frame)\n"
                                           : std::string())
            << "initial gap      min " << c.initial_gap.minCoeff() << ", max " << c.initial_gap.maxCoeff() << "\n"
            << "search direction " << searchLawFormula(scene.search_direction.law) << ": kappa = " << scene.search_direction.scale
            << ", L = "
            << p.length_scale << ", kappa E / L = " << c.search_scale_per_length << ", k in ["
            << c.search_direction.minCoeff() << ", " << c.search_direction.maxCoeff() << "]\n"
            << "solver           " << scene.solver.name() << ", tolerance " << scene.solver.tolerance() << "\n"
            << "outputs          " << outputsLine(scene.output, p) << "\n";
  return 0;
}

}  // namespace stc::cli
