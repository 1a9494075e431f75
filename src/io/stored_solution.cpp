#include "stcontact/io/stored_solution.hpp"

#include <limits>

#include "stcontact/core/input_error.hpp"
#include "stcontact/io/hdf5_reader.hpp"

namespace stc {
namespace {

constexpr const char* kFormat = "stcontact solution";  // solution_file.cpp's "format"

// /interface/force, instant × contact node × component, as SolveResult's d n_C × m.
Eigen::MatrixXd forcesOf(const h5::Reader& file, const StoredSolution& s) {
  h5::DoubleArray force = file.doubles("/interface/force");
  const std::vector<std::uint64_t> expected{static_cast<std::uint64_t>(s.steps),
                                            static_cast<std::uint64_t>(s.contact_nodes),
                                            static_cast<std::uint64_t>(s.dimension)};
  if (force.dims != expected)
    throw InputError("cannot read '" + file.where("/interface/force") +
                     "': its shape is not instants × contact nodes × " + std::to_string(s.dimension) +
                     " as the file's attributes say");
  // Row-major (instant, node, component) is column-major (node component, instant): the same bytes.
  const Eigen::Index rows = static_cast<Eigen::Index>(s.dimension) * s.contact_nodes;
  return Eigen::Map<Eigen::MatrixXd>(force.values.data(), rows, s.steps);
}

std::string sizes(int dimension, long long dofs, int nodes, int steps) {
  return std::to_string(dimension) + "D, " + std::to_string(dofs) + " dofs, " + std::to_string(nodes) +
         " contact nodes, " + std::to_string(steps) + " instants";
}

}  // namespace

StoredSolution readStoredSolution(const std::filesystem::path& path) {
  const h5::Reader file(path);
  if (!file.hasAttribute("format") || file.text("format") != kFormat)
    throw InputError("cannot read '" + path.string() + "': not a solution written by stcontact (no format attribute '" +
                     kFormat + "')");
  StoredSolution s;
  s.file = path.string();
  s.solver = file.text("solver");
  s.model_json = file.hasAttribute("model") ? file.text("model") : "";
  s.dimension = static_cast<int>(file.number("dimension"));
  s.dofs = static_cast<long long>(file.number("n_dofs"));
  s.contact_nodes = static_cast<int>(file.number("n_contact_nodes"));
  s.steps = static_cast<int>(file.number("n_steps"));
  const double estimate = file.number("error_estimate");
  s.error_estimate = estimate > 0.0 ? estimate : std::numeric_limits<double>::quiet_NaN();
  s.error = file.number("error");
  s.lambda = forcesOf(file, s);
  return s;
}

void requireSolvedOn(const StoredSolution& stored, const Problem& problem, const std::string& model_json) {
  const std::string what = "'" + stored.file + "' was not solved on this scene";
  if (stored.dimension != problem.dimension || stored.dofs != problem.numDofs() ||
      stored.contact_nodes != problem.contact.size() || stored.steps != problem.numSteps())
    throw InputError(what + ": it holds " + sizes(stored.dimension, stored.dofs, stored.contact_nodes, stored.steps) +
                     ", the scene has " +
                     sizes(problem.dimension, problem.numDofs(), problem.contact.size(), problem.numSteps()) +
                     " (give the same --set as the run)");
  if (stored.model_json.empty())
    throw InputError(what + ": the file does not record its model (written before stcontact kept it): solve again");
  if (stored.model_json != model_json)
    throw InputError(what + ": the model differs ([solver] and [output] aside; give the scene and the --set of the "
                            "run; the file's 'model' attribute holds what was solved)");
}

}  // namespace stc
