#pragma once
// solution.h5 and its XDMF index solution.xdmf (docs/interface.md, "solution.h5 and solution.xdmf"): one HDF5 file per
// run holding the mesh once, the interface histories as arrays (instant × contact node ×
// component), the reactions and the iteration history, the frames' fields at output instants
// (compressed, one dataset per field and instant) and the summary's figures as attributes; the
// XDMF file lists the frames as a temporal collection for ParaView (Xdmf3 reader), meshio and
// VisIt. XDMF model: https://www.xdmf.org/index.php/XDMF_Model_and_Format (version 3).
#include <filesystem>
#include <string>
#include <vector>

#include "stcontact/io/contact_tables.hpp"
#include "stcontact/io/frame_fields.hpp"
#include "stcontact/problem/problem.hpp"
#include "stcontact/scene/output_spec.hpp"
#include "stcontact/solver/solve_result.hpp"

namespace stc {

/// The frames to write into the file: their instants and where their displacement comes from; none
/// (null `displacement`) writes no frame.
struct FramePlan {
  std::vector<int> steps;
  FrameDisplacement* displacement = nullptr;
  FieldPrecision precision = FieldPrecision::Float32;
};

/// What the file records beside the solution: the stcontact version and the scene as read.
struct SolutionFileInfo {
  std::string version;
  std::string parameters_json = "{}";
  std::string model_json = "{}";  ///< the scene without [solver] and [output] (Scene::model_json)
};

/// The tables the run's files share, computed once (io/contact_tables.hpp).
struct RunTables {
  InterfaceTable interface;
  ReactionTable reactions;
};

/// Writes `path` (solution.h5), replacing it. Throws OutputError naming the file and the object that
/// failed.
void writeSolutionH5(const std::filesystem::path& path, const Problem& problem, const SolveResult& result,
                     const RunTables& tables, const SolutionFileInfo& info, const FramePlan& frames);

/// The XDMF document indexing the frames of `h5_name` (relative to the XDMF file): one uniform grid
/// per frame in a temporal collection, the mesh's datasets shared.
std::string xdmfDocument(const std::string& h5_name, const Problem& problem, const std::vector<int>& frame_steps,
                         FieldPrecision precision);

/// The name of frame k's group, "step_NNNNN", and its path in solution.h5, "/frames/step_NNNNN".
std::string frameName(int k);
std::string frameGroup(int k);

}  // namespace stc
