#include "stcontact/io/vtu_writer.hpp"

#include <bit>
#include <charconv>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string_view>

#include "stcontact/io/text_buffer.hpp"

namespace stc {
namespace {

constexpr int kVtkTriangle = 5;
constexpr int kVtkTetra = 10;
constexpr const char* kByteOrder = std::endian::native == std::endian::little ? "LittleEndian" : "BigEndian";

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

/// Where the data of each of `arrays` (in XML order) starts in the appended data, which holds them in
/// reverse order.
std::vector<std::size_t> reverseOffsets(const std::vector<const EncodedArray*>& arrays) {
  std::vector<std::size_t> offsets(arrays.size());
  std::size_t at = 0;
  for (std::size_t i = arrays.size(); i-- > 0;) {
    offsets[i] = at;
    at += arrays[i]->blocks.size();
  }
  return offsets;
}

/// The DataArray element of `array`, its data `offset` bytes into the appended data.
void arrayTag(TextBuffer& xml, const EncodedArray& array, std::size_t offset) {
  xml.text("        <DataArray type=\"").text(array.type).text("\" Name=\"").text(escapeXml(array.name));
  xml.text("\" NumberOfComponents=\"").integer(array.components).put('"');
  for (std::size_t i = 0; i < array.componentNames.size(); ++i)
    xml.text(" ComponentName").integer(static_cast<long long>(i)).text("=\"").text(array.componentNames[i]).put('"');
  xml.text(" format=\"appended\" offset=\"").integer(static_cast<long long>(offset)).text("\"/>\n");
}

/// Opening tag of PointData/CellData: the first scalar, vector and symmetric tensor fields become the
/// active ones.
template <typename Field>
void openData(TextBuffer& xml, const char* tag, const std::vector<Field>& fields) {
  const auto declare = [&](const char* attribute, auto isOne) {
    for (const Field& field : fields)
      if (isOne(field)) {
        xml.put(' ').text(attribute).text("=\"").text(escapeXml(field.name)).put('"');
        return;
      }
  };
  xml.text("      <").text(tag);
  declare("Scalars", [](const Field& f) { return storedComponents(f.kind, f.values.rows()) == 1; });
  declare("Vectors", [](const Field& f) { return f.kind == FieldKind::Real && f.values.rows() >= 2; });
  declare("Tensors", [](const Field& f) { return f.kind == FieldKind::SymmetricTensor; });
  xml.text(">\n");
}

template <typename Field>
void encodeFields(const std::vector<Field>& fields, FieldPrecision precision, std::vector<EncodedArray>& arrays) {
  for (const Field& field : fields) arrays.push_back(encodedField(field.name, field.values, field.kind, precision));
}

}  // namespace

VtuGrid::VtuGrid(const TriMesh& mesh, FieldPrecision precision)
    : points_(mesh.nodes.cols()),
      cells_(mesh.triangles.cols()),
      precision_(precision),
      pointArray_(pointArray(mesh.nodes, precision)),
      cellArrays_(cellArrays(mesh.triangles, points_, kVtkTriangle)) {}

VtuGrid::VtuGrid(const TetMesh& mesh, FieldPrecision precision)
    : points_(mesh.nodes.cols()),
      cells_(mesh.tets.cols()),
      precision_(precision),
      pointArray_(pointArray(mesh.nodes, precision)),
      cellArrays_(cellArrays(mesh.tets, points_, kVtkTetra)) {}

void VtuGrid::write(std::ostream& out, const std::vector<PointField>& pointFields,
                    const std::vector<CellField>& cellFields) const {
  checkFields(pointFields, points_, precision_);
  checkFields(cellFields, cells_, precision_);
  std::vector<EncodedArray> fields;
  encodeFields(pointFields, precision_, fields);
  encodeFields(cellFields, precision_, fields);
  std::vector<const EncodedArray*> arrays;  // in XML order
  for (const EncodedArray& array : fields) arrays.push_back(&array);
  arrays.push_back(&pointArray_);
  for (const EncodedArray& array : cellArrays_) arrays.push_back(&array);
  const std::vector<std::size_t> offsets = reverseOffsets(arrays);
  std::size_t next = 0;
  TextBuffer xml;
  const auto tags = [&](std::size_t count) {
    for (; count > 0; --count, ++next) arrayTag(xml, *arrays[next], offsets[next]);
  };
  xml.text("<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"")
      .text(kByteOrder)
      .text("\" header_type=\"UInt64\" compressor=\"vtkZLibDataCompressor\">\n  <UnstructuredGrid>\n")
      .text("    <Piece NumberOfPoints=\"")
      .integer(points_)
      .text("\" NumberOfCells=\"")
      .integer(cells_)
      .text("\">\n");
  openData(xml, "PointData", pointFields);
  tags(pointFields.size());
  xml.text("      </PointData>\n");
  openData(xml, "CellData", cellFields);
  tags(cellFields.size());
  xml.text("      </CellData>\n      <Points>\n");
  tags(1);
  xml.text("      </Points>\n      <Cells>\n");
  tags(cellArrays_.size());
  xml.text("      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n  <AppendedData encoding=\"raw\">\n   _");
  xml.flushTo(out);
  for (auto it = arrays.rbegin(); it != arrays.rend(); ++it)
    out.write((*it)->blocks.data(), static_cast<std::streamsize>((*it)->blocks.size()));
  out << "\n  </AppendedData>\n</VTKFile>\n";
}

void writeVtu(std::ostream& out, const TriMesh& mesh, const std::vector<PointField>& pointFields,
              const std::vector<CellField>& cellFields, FieldPrecision precision) {
  VtuGrid(mesh, precision).write(out, pointFields, cellFields);
}

void writeVtu(std::ostream& out, const TetMesh& mesh, const std::vector<PointField>& pointFields,
              const std::vector<CellField>& cellFields, FieldPrecision precision) {
  VtuGrid(mesh, precision).write(out, pointFields, cellFields);
}

std::string vtuDocument(const TriMesh& mesh, const std::vector<PointField>& pointFields,
                        const std::vector<CellField>& cellFields, FieldPrecision precision) {
  std::ostringstream out;
  writeVtu(out, mesh, pointFields, cellFields, precision);
  return out.str();
}

std::string vtuDocument(const TetMesh& mesh, const std::vector<PointField>& pointFields,
                        const std::vector<CellField>& cellFields, FieldPrecision precision) {
  std::ostringstream out;
  writeVtu(out, mesh, pointFields, cellFields, precision);
  return out.str();
}

std::string pvdDocument(const std::vector<PvdDataSet>& frames) {
  std::ostringstream out;
  out << "<?xml version=\"1.0\"?>\n"
      << "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      << "  <Collection>\n";
  for (const auto& [time, file, part, name] : frames) {
    if (file.empty())
      throw std::invalid_argument("PVD frame at time " + std::to_string(time) +
                                  ": empty file name");
    if (!std::isfinite(time))
      throw std::invalid_argument("PVD frame '" + file + "': non-finite time");
    if (part < 0) throw std::invalid_argument("PVD frame '" + file + "': negative part");
    char buffer[32];  // shortest exact form: close instants stay distinct
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, time);
    out << "    <DataSet timestep=\"" << std::string_view(buffer, result.ptr - buffer)
        << "\" group=\"\" part=\"" << part << "\" file=\"" << escapeXml(file) << '"';
    if (!name.empty()) out << " name=\"" << escapeXml(name) << '"';
    out << "/>\n";
  }
  out << "  </Collection>\n"
      << "</VTKFile>\n";
  return out.str();
}

}  // namespace stc
