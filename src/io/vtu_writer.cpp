#include "stcontact/io/vtu_writer.hpp"

#include <charconv>
#include <cmath>
#include <limits>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string_view>

#include "stcontact/io/text_buffer.hpp"

namespace stc {
namespace {

/// Significant digits of floating-point values in .vtu files: a relative rounding of 5e-11, far
/// below any solver tolerance and any visible difference, at about 60% of the size of the 17
/// digits an exact round trip needs. The files are for viewing; exact numbers go to the CSV and
/// JSON outputs.
constexpr int kVtuDigits = 10;
constexpr int kScalarsPerLine = 12;  ///< one-component arrays; larger tuples take a line each
constexpr int kVtkTriangle = 5;
constexpr int kVtkTetra = 10;
constexpr const char* kDataIndent = "          ";  ///< the values, one level inside DataArray

/// `text` with the five XML special characters replaced by entities, for attribute values.
std::string escapeXml(std::string_view text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default: out += c;
    }
  }
  return out;
}

[[noreturn]] void badField(const char* kind, const std::string& name, const std::string& rule) {
  throw std::invalid_argument(std::string("VTU ") + kind + " field '" + name + "': " + rule);
}

/// Checks names (non-empty, unique), sizes and finiteness of one kind of field.
template <typename Field>
void validateFields(const std::vector<Field>& fields, const char* kind, int columns,
                    const char* columnName, int maxRows) {
  std::set<std::string> names;
  for (const Field& field : fields) {
    const auto& values = field.values;
    if (field.name.empty()) badField(kind, field.name, "the name is empty");
    if (!names.insert(field.name).second) badField(kind, field.name, "the name is repeated");
    if (values.rows() < 1 || values.rows() > maxRows)
      badField(
          kind, field.name,
          std::to_string(values.rows()) + " components, expected 1 to " + std::to_string(maxRows));
    if (values.cols() != columns)
      badField(kind, field.name,
               std::to_string(values.cols()) + " columns, the mesh has " + std::to_string(columns) +
                   " " + columnName);
    for (Eigen::Index j = 0; j < values.cols(); ++j)
      if (!values.col(j).allFinite())
        badField(kind, field.name, "non-finite value at column " + std::to_string(j));
  }
}

/// A Float64 DataArray of `values` (rows = components, cols = tuples); rows beyond those of
/// `values`, up to `components`, are written as 0.
void writeFloatArray(TextBuffer& out, const std::string& name, const Eigen::Ref<const Eigen::MatrixXd>& values,
                     Eigen::Index components) {
  out.text("        <DataArray type=\"Float64\" Name=\"").text(escapeXml(name)).text("\" NumberOfComponents=\"")
      .integer(components).text("\" format=\"ascii\">\n");
  const Eigen::Index perLine = components == 1 ? kScalarsPerLine : 1;
  for (Eigen::Index j = 0; j < values.cols(); ++j) {
    out.text(j % perLine == 0 ? kDataIndent : " ");
    for (Eigen::Index i = 0; i < components; ++i) {
      if (i > 0) out.put(' ');
      out.number(i < values.rows() ? values(i, j) : 0.0, kVtuDigits);
    }
    if ((j + 1) % perLine == 0 || j + 1 == values.cols()) out.put('\n');
  }
  out.text("        </DataArray>\n");
}

/// An integer DataArray of `count` values value(k), `perLine` to a line.
template <typename ValueAt>
void writeIntArray(TextBuffer& out, const char* type, const char* name, Eigen::Index count, Eigen::Index perLine,
                   ValueAt value) {
  out.text("        <DataArray type=\"").text(type).text("\" Name=\"").text(name).text("\" format=\"ascii\">\n");
  for (Eigen::Index k = 0; k < count; ++k) {
    out.text(k % perLine == 0 ? kDataIndent : " ").integer(value(k));
    if ((k + 1) % perLine == 0 || k + 1 == count) out.put('\n');
  }
  out.text("        </DataArray>\n");
}

/// Opening tag of PointData/CellData; the first vector and scalar fields become the active ones.
template <typename Field>
void openData(TextBuffer& out, const char* tag, const std::vector<Field>& fields) {
  out.text("      <").text(tag);
  for (const Field& field : fields)
    if (field.values.rows() == 1) {
      out.text(" Scalars=\"").text(escapeXml(field.name)).put('"');
      break;
    }
  if (std::string_view(tag) == "PointData")
    for (const Field& field : fields)
      if (field.values.rows() >= 2) {
        out.text(" Vectors=\"").text(escapeXml(field.name)).put('"');
        break;
      }
  out.text(">\n");
}

/// Components written for a point field: plane vectors get z = 0 (Warp By Vector needs 3).
Eigen::Index paddedComponents(Eigen::Index rows) { return rows == 2 ? 3 : rows; }

/// Cells of one type, `cells` holding the node ids of each (one column per cell).
template <typename Cells>
void writeCells(TextBuffer& out, const Cells& cells, int vtkType) {
  const Eigen::Index n = cells.cols(), k = cells.rows();
  out.text("      <Cells>\n");
  writeIntArray(out, "Int64", "connectivity", k * n, k, [&](Eigen::Index j) { return cells(j % k, j / k); });
  writeIntArray(out, "Int64", "offsets", n, kScalarsPerLine, [k](Eigen::Index e) { return k * (e + 1); });
  writeIntArray(out, "UInt8", "types", n, kScalarsPerLine, [vtkType](Eigen::Index) { return vtkType; });
  out.text("      </Cells>\n");
}

/// The <Points> and <Cells> elements for points (2 or 3 rows; z = 0 when 2) and cells of one VTK type.
template <typename Points, typename Cells>
std::string geometryText(const Points& points, const Cells& cells, int vtkType) {
  TextBuffer out;
  out.text("      <Points>\n");
  writeFloatArray(out, "Points", points, 3);
  out.text("      </Points>\n");
  writeCells(out, cells, vtkType);
  return out.str();
}

}  // namespace

VtuGrid::VtuGrid(const TriMesh& mesh)
    : points_(mesh.nodes.cols()),
      cells_(mesh.triangles.cols()),
      geometry_(geometryText(mesh.nodes, mesh.triangles, kVtkTriangle)) {}

VtuGrid::VtuGrid(const TetMesh& mesh)
    : points_(mesh.nodes.cols()), cells_(mesh.tets.cols()), geometry_(geometryText(mesh.nodes, mesh.tets, kVtkTetra)) {}

void VtuGrid::write(std::ostream& out, const std::vector<PointField>& pointFields,
                    const std::vector<CellField>& cellFields) const {
  validateFields(pointFields, "point", static_cast<int>(points_), "nodes", 3);
  validateFields(cellFields, "cell", static_cast<int>(cells_), "elements", std::numeric_limits<int>::max());
  TextBuffer text;
  text.text("<?xml version=\"1.0\"?>\n"
            "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
            "  <UnstructuredGrid>\n"
            "    <Piece NumberOfPoints=\"")
      .integer(points_)
      .text("\" NumberOfCells=\"")
      .integer(cells_)
      .text("\">\n");
  openData(text, "PointData", pointFields);
  for (const PointField& field : pointFields)
    writeFloatArray(text, field.name, field.values, paddedComponents(field.values.rows()));
  text.text("      </PointData>\n");
  openData(text, "CellData", cellFields);
  for (const CellField& field : cellFields) writeFloatArray(text, field.name, field.values, field.values.rows());
  text.text("      </CellData>\n").text(geometry_).text("    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n");
  text.flushTo(out);
}

void writeVtu(std::ostream& out, const TriMesh& mesh, const std::vector<PointField>& pointFields,
              const std::vector<CellField>& cellFields) {
  VtuGrid(mesh).write(out, pointFields, cellFields);
}

void writeVtu(std::ostream& out, const TetMesh& mesh, const std::vector<PointField>& pointFields,
              const std::vector<CellField>& cellFields) {
  VtuGrid(mesh).write(out, pointFields, cellFields);
}

std::string vtuDocument(const TriMesh& mesh, const std::vector<PointField>& pointFields,
                        const std::vector<CellField>& cellFields) {
  std::ostringstream out;
  writeVtu(out, mesh, pointFields, cellFields);
  return out.str();
}

std::string vtuDocument(const TetMesh& mesh, const std::vector<PointField>& pointFields,
                        const std::vector<CellField>& cellFields) {
  std::ostringstream out;
  writeVtu(out, mesh, pointFields, cellFields);
  return out.str();
}

std::string pvdDocument(const std::vector<std::pair<double, std::string>>& frames) {
  std::ostringstream out;
  out << "<?xml version=\"1.0\"?>\n"
      << "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      << "  <Collection>\n";
  for (const auto& [time, file] : frames) {
    if (file.empty())
      throw std::invalid_argument("PVD frame at time " + std::to_string(time) +
                                  ": empty file name");
    if (!std::isfinite(time))
      throw std::invalid_argument("PVD frame '" + file + "': non-finite time");
    char buffer[32];  // shortest exact form: close instants stay distinct
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, time);
    out << "    <DataSet timestep=\"" << std::string_view(buffer, result.ptr - buffer)
        << "\" group=\"\" part=\"0\" file=\"" << escapeXml(file) << "\"/>\n";
  }
  out << "  </Collection>\n"
      << "</VTKFile>\n";
  return out.str();
}

}  // namespace stc
