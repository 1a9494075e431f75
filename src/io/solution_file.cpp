#include "stcontact/io/solution_file.hpp"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <sstream>

#include "stcontact/core/threads.hpp"
#include "stcontact/io/contact_tables.hpp"
#include "stcontact/io/hdf5_file.hpp"
#include "stcontact/mesh/connected_parts.hpp"
#include "stcontact/spacetime/contact_state_table.hpp"

namespace stc {
namespace {

using Dims = std::vector<std::uint64_t>;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::uint64_t u64(long long n) { return static_cast<std::uint64_t>(n); }

// A d × n matrix (one column per item) as the rows of an n × width array (width ≥ d: ParaView's
// vectors have three components, z = 0 in 2D), in T.
template <class T>
std::vector<T> rowsOf(const Eigen::MatrixXd& columns, int width) {
  std::vector<T> out(static_cast<std::size_t>(columns.cols()) * static_cast<std::size_t>(width), T(0));
  for (Eigen::Index j = 0; j < columns.cols(); ++j)
    for (Eigen::Index a = 0; a < columns.rows(); ++a)
      out[static_cast<std::size_t>(j) * static_cast<std::size_t>(width) + static_cast<std::size_t>(a)] =
          static_cast<T>(columns(a, j));
  return out;
}

// The field `values` (rows = components, one column per item) encoded in the frames' precision:
// vectors and tensors as items × width, scalars as items.
h5::Encoded encodedField(const Eigen::MatrixXd& values, int width, FieldPrecision precision) {
  const Dims dims = width == 1 ? Dims{u64(values.cols())} : Dims{u64(values.cols()), u64(width)};
  if (precision == FieldPrecision::Float32) return h5::encode(rowsOf<float>(values, width).data(), dims);
  return h5::encode(rowsOf<double>(values, width).data(), dims);
}

// The width a frame field is written with: vectors padded to 3, tensors 6, scalars 1.
int widthOf(const Eigen::MatrixXd& values, FieldKind kind) {
  if (kind == FieldKind::SymmetricTensor) return 6;
  return values.rows() == 1 ? 1 : 3;
}

void writeMesh(const h5::Group& root, const Problem& problem) {
  const h5::Group mesh = root.group("mesh");
  const Eigen::MatrixXd x = problem.nodePositions();
  const Dims points{u64(x.cols()), 3};
  mesh.write("points", rowsOf<double>(x, 3).data(), points, h5::chunkedByRows(points, sizeof(double)));
  const std::vector<int> node_body = partOfNodes(problem.body);
  std::vector<int> cell_body(static_cast<std::size_t>(problem.numElements()), 0);
  std::visit(
      [&](const auto& m) {
        const auto& cells = elementNodes(m);
        const Dims dims{u64(cells.cols()), u64(cells.rows())};  // column-major: each element's nodes together
        mesh.write("cells", cells.data(), dims, h5::chunkedByRows(dims, sizeof(int)));
        mesh.attribute("cell_type", cells.rows() == 3 ? "triangle" : "tetrahedron");
        for (Eigen::Index e = 0; e < cells.cols(); ++e)  // an element's body is its nodes'
          cell_body[static_cast<std::size_t>(e)] = node_body[static_cast<std::size_t>(cells(0, e))];
      },
      problem.body);
  const std::vector<long long> tags = nodeTags(problem.body);
  const std::vector<std::int64_t> node_tags(tags.begin(), tags.end());
  mesh.write("node_tags", node_tags, h5::chunkedByRows({u64(node_tags.size())}, sizeof(std::int64_t)));
  mesh.write("node_body", node_body, h5::chunkedByRows({u64(node_body.size())}, sizeof(int)));
  mesh.write("cell_body", cell_body, h5::chunkedByRows({u64(cell_body.size())}, sizeof(int)));
}

void writeContact(const h5::Group& root, const Problem& problem) {
  const auto& c = problem.contact;
  const h5::Group contact = root.group("contact");
  contact.write("nodes", c.nodes);
  const std::vector<long long> tags = nodeTags(problem.body);
  std::vector<std::int64_t> contact_tags;
  for (int node : c.nodes) contact_tags.push_back(tags[static_cast<std::size_t>(node)]);
  contact.write("node_tags", contact_tags);
  contact.write("tributary", c.tributary.data(), {u64(c.size())});
  contact.write("initial_gap", c.initial_gap.data(), {u64(c.size())});
  contact.write("normals", c.normals.data(), {u64(c.normals.cols()), u64(c.normals.rows())});
  contact.write("tangents", c.tangents.data(), {u64(c.tangents.cols()), u64(c.tangents.rows())});
}

// The interface histories, instant × contact node × component (io/contact_tables.hpp, InterfaceTable).
void writeInterface(const h5::Group& root, const SolveResult& result, const InterfaceTable& table) {
  const h5::Group interface = root.group("interface");
  const std::uint64_t m = u64(table.steps), n = u64(table.nodes), t = u64(table.tangential);
  // Chunks of 32 contact nodes: the nodes that never touch (most of them) leave force, slip and state
  // chunks of zeros, which are not written.
  const auto put = [&](const std::string& name, const auto* data, const Dims& dims) {
    interface.write(name, data, dims, h5::chunkedByBlocks(dims, sizeof(*data), 32));
  };
  // λ: column k is instant k, its rows (node, component): pressure and shear are these over
  // /contact/tributary (not stored twice)
  put("force", result.interface.lambda.data(), {m, n, t + 1});
  put("gap", table.gap.data(), {m, n});
  put("slip", table.slip.data(), {m, n, t});
  put("state", table.state.data(), {m, n});
}

void writeReactions(const h5::Group& root, const ReactionTable& table) {
  const h5::Group reactions = root.group("reactions");
  reactions.write("normal_force", table.normal_force);
  reactions.write("tangential_force", table.tangential_force);
  if (!table.tangential_force_2.empty()) reactions.write("tangential_force_2", table.tangential_force_2);
  reactions.write("contact_xmin", table.contact_xmin);
  reactions.write("contact_xmax", table.contact_xmax);
  reactions.write("n_contact", table.n_contact);
  reactions.write("n_slip", table.n_slip);
  reactions.write("force", rowsOf<double>(table.force, static_cast<int>(table.force.rows())).data(),
                  {u64(table.force.cols()), u64(table.force.rows())});
}

void writeHistory(const h5::Group& root, const SolveSummary& summary) {
  const h5::Group history = root.group("history");
  std::vector<int> iteration, relaxations, rank, sparse_solves;
  std::vector<double> indicator, error, wall_s, error_estimate;
  std::vector<std::int64_t> krylov;
  for (const IterationRecord& r : summary.history) {
    iteration.push_back(r.iteration);
    relaxations.push_back(r.relaxations);
    indicator.push_back(r.indicator);
    error.push_back(r.error.value_or(kNaN));
    rank.push_back(r.rank);
    wall_s.push_back(r.wall_s);
    error_estimate.push_back(std::isfinite(r.error_estimate) ? r.error_estimate : kNaN);
    sparse_solves.push_back(r.sparse_solves);
    krylov.push_back(r.krylov_iterations);
  }
  history.write("iteration", iteration);
  history.write("relaxations", relaxations);
  history.write("indicator", indicator);
  history.write("error", error);
  history.write("rank", rank);
  history.write("wall_s", wall_s);
  history.write("error_estimate", error_estimate);
  history.write("sparse_solves", sparse_solves);
  history.write("krylov_iterations", krylov);
}

void writeAttributes(const h5::Group& root, const Problem& problem, const SolveSummary& summary,
                     const SolutionFileInfo& info) {
  root.attribute("format", "stcontact solution");
  root.attribute("format_version", 1);
  root.attribute("version", info.version);
  root.attribute("solver", summary.solver);
  root.attribute("termination", toString(summary.termination));
  root.attribute("message", summary.message);
  if (!summary.incremental_form.empty()) root.attribute("incremental_form", summary.incremental_form);
  root.attribute("iterations", summary.iterations);
  root.attribute("relaxations", summary.relaxations);
  root.attribute("sparse_solves", summary.sparseSolves());
  root.attribute("krylov_iterations", static_cast<std::int64_t>(summary.krylov_iterations));
  root.attribute("indicator", summary.indicator);
  root.attribute("error_estimate", std::isfinite(summary.error_estimate) ? summary.error_estimate : kNaN);
  root.attribute("error", summary.error.value_or(kNaN));
  root.attribute("wall_s", summary.wall_s);
  root.attribute("dimension", problem.dimension);
  root.attribute("n_dofs", problem.numDofs());
  root.attribute("n_contact_nodes", problem.contact.size());
  root.attribute("n_steps", problem.numSteps());
  root.attribute("parameters", info.parameters_json);
  root.attribute("model", info.model_json);
}

// A frame's datasets, named and encoded.
using EncodedFrame = std::vector<std::pair<std::string, h5::Encoded>>;

EncodedFrame encodedFrame(const FrameFields& fields, FieldPrecision precision) {
  EncodedFrame out;
  for (const PointField& f : fields.nodal) out.emplace_back(f.name, encodedField(f.values, widthOf(f.values, f.kind), precision));
  for (const CellField& f : fields.cells) out.emplace_back(f.name, encodedField(f.values, widthOf(f.values, f.kind), precision));
  return out;
}

// The frames, formed and encoded a batch at a time on every thread, written in order by this one
// (HDF5 is called from one thread only).
void writeFrames(const h5::Group& root, const Problem& problem, const SolveResult& result, const FramePlan& plan) {
  const h5::Group frames = root.group("frames");
  std::vector<double> times;
  for (int k : plan.steps) times.push_back(problem.times[static_cast<std::size_t>(k)]);
  frames.write("steps", plan.steps);
  frames.write("time", times);
  const ContactStateTable states = result.contactStates(problem.contact);
  const int threads = threadCount();
  const int count = static_cast<int>(plan.steps.size());
  for (int first = 0; first < count; first += 2 * threads) {
    const int batch = std::min(2 * threads, count - first);
    std::vector<EncodedFrame> encoded(static_cast<std::size_t>(batch));
    parallelFor(batch, threads, [&](int item, int thread) {
      const int k = plan.steps[static_cast<std::size_t>(first + item)];
      encoded[static_cast<std::size_t>(item)] =
          encodedFrame(frameFields(problem, result, states, k, plan.displacement->at(k, thread)), plan.precision);
    });
    for (int item = 0; item < batch; ++item) {
      const int k = plan.steps[static_cast<std::size_t>(first + item)];
      const h5::Group frame = frames.group(frameName(k));
      for (const auto& [name, data] : encoded[static_cast<std::size_t>(item)]) frame.write(name, data);
    }
  }
}

}  // namespace

std::string frameName(int k) {
  char name[32];
  std::snprintf(name, sizeof name, "step_%05d", k);
  return name;
}

std::string frameGroup(int k) { return "/frames/" + frameName(k); }

void writeSolutionH5(const std::filesystem::path& path, const Problem& problem, const SolveResult& result,
                     const RunTables& tables, const SolutionFileInfo& info, const FramePlan& frames) {
  h5::File file(path);
  const h5::Group& root = file.root();
  writeAttributes(root, problem, result.summary, info);
  root.write("time", problem.times);
  writeMesh(root, problem);
  writeContact(root, problem);
  writeInterface(root, result, tables.interface);
  writeReactions(root, tables.reactions);
  writeHistory(root, result.summary);
  if (frames.displacement && !frames.steps.empty()) writeFrames(root, problem, result, frames);
  file.close();
}

namespace {

std::string dataItem(const std::string& h5, const std::string& dataset, const std::string& dims, const char* type,
                     int precision) {
  std::ostringstream out;
  out << "<DataItem Dimensions=\"" << dims << "\" NumberType=\"" << type << "\" Precision=\"" << precision
      << "\" Format=\"HDF\">" << h5 << ':' << dataset << "</DataItem>";
  return out.str();
}

}  // namespace

std::string xdmfDocument(const std::string& h5, const Problem& problem, const std::vector<int>& frame_steps,
                         FieldPrecision precision) {
  const int d = problem.dimension, n = problem.numNodes(), e = problem.numElements();
  const int bytes = precision == FieldPrecision::Float32 ? 4 : 8;
  const std::string nodes = std::to_string(n), cells = std::to_string(e);
  const std::string topology = "      <Topology TopologyType=\"" + std::string(d == 2 ? "Triangle" : "Tetrahedron") +
                               "\" NumberOfElements=\"" + cells + "\">\n        " +
                               dataItem(h5, "/mesh/cells", cells + " " + std::to_string(d + 1), "Int", 4) +
                               "\n      </Topology>\n";
  const std::string geometry = "      <Geometry GeometryType=\"XYZ\">\n        " +
                               dataItem(h5, "/mesh/points", nodes + " 3", "Float", 8) + "\n      </Geometry>\n";
  const bool bodies = problem.contact.isPair();
  std::ostringstream out;
  out.precision(17);
  out << "<?xml version=\"1.0\"?>\n<Xdmf Version=\"3.0\">\n  <Domain>\n"
      << "    <Grid Name=\"solution\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  for (int k : frame_steps) {
    const std::string group = frameGroup(k);
    const auto attribute = [&](const char* name, const char* kind, const char* center, const std::string& dims,
                               const std::string& dataset, const char* type, int precision_bytes) {
      out << "      <Attribute Name=\"" << name << "\" AttributeType=\"" << kind << "\" Center=\"" << center
          << "\">\n        " << dataItem(h5, dataset, dims, type, precision_bytes) << "\n      </Attribute>\n";
    };
    out << "     <Grid Name=\"step_" << k << "\" GridType=\"Uniform\">\n"
        << "      <Time Value=\"" << problem.times[static_cast<std::size_t>(k)] << "\"/>\n"
        << topology << geometry;
    attribute("displacement", "Vector", "Node", nodes + " 3", group + "/displacement", "Float", bytes);
    attribute("contact_force", "Vector", "Node", nodes + " 3", group + "/contact_force", "Float", bytes);
    attribute("contact_state", "Scalar", "Node", nodes, group + "/contact_state", "Float", bytes);
    attribute("stress", "Tensor6", "Cell", cells + " 6", group + "/stress", "Float", bytes);
    attribute("von_mises", "Scalar", "Cell", cells, group + "/von_mises", "Float", bytes);
    if (bodies) attribute("body", "Scalar", "Cell", cells, "/mesh/cell_body", "Int", 4);
    out << "     </Grid>\n";
  }
  out << "    </Grid>\n  </Domain>\n</Xdmf>\n";
  return out.str();
}

}  // namespace stc
