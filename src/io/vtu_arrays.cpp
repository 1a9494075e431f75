#include "stcontact/io/vtu_arrays.hpp"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <set>
#include <sstream>
#include <stdexcept>

#include "stcontact/io/vtk_zlib_blocks.hpp"

namespace stc {
namespace {

const std::vector<std::string> kVectorNames = {"X", "Y", "Z"};
const std::vector<std::string> kTensorNames = {"XX", "YY", "ZZ", "XY", "YZ", "XZ"};

std::string shortNumber(double value) {
  std::ostringstream text;
  text << value;
  return text.str();
}

[[noreturn]] void badField(const char* where, const std::string& name, const std::string& rule) {
  throw std::invalid_argument(std::string("VTU ") + where + " field '" + name + "': " + rule);
}

/// Rows a field of this kind may have: [first, second].
std::pair<Eigen::Index, Eigen::Index> rowRange(FieldKind kind) {
  switch (kind) {
    case FieldKind::Code: return {1, 1};
    case FieldKind::SymmetricTensor: return {6, 6};
    default: return {1, 3};
  }
}

const std::vector<std::string>& componentNames(FieldKind kind, Eigen::Index rows) {
  static const std::vector<std::string> none;
  if (kind == FieldKind::SymmetricTensor) return kTensorNames;
  return rows >= 2 ? kVectorNames : none;
}

/// Whether `value` can be stored in a field of this kind: finite, an Int8 integer for a code, within
/// float's range for Float32.
bool storable(double value, FieldKind kind, FieldPrecision precision) {
  if (!std::isfinite(value)) return false;
  if (kind == FieldKind::Code) return value == std::round(value) && value >= -128 && value <= 127;
  return precision == FieldPrecision::Float64 || std::abs(value) <= std::numeric_limits<float>::max();
}

/// What is wrong with a value that is not storable.
std::string valueProblem(double value, FieldKind kind) {
  if (!std::isfinite(value)) return "non-finite value";
  if (kind == FieldKind::Code) return "value " + shortNumber(value) + " is not an integer in [-128, 127] (Int8)";
  return "value " + shortNumber(value) +
         " is beyond Float32's range (|x| <= 3.4e38); write Float64 (output.field_precision = \"float64\")";
}

template <typename Field>
void checkFieldsOf(const std::vector<Field>& fields, const char* where, Eigen::Index columns, const char* columnName,
                   FieldPrecision precision) {
  std::set<std::string> names;
  for (const Field& field : fields) {
    const auto& values = field.values;
    if (field.name.empty()) badField(where, field.name, "the name is empty");
    if (!names.insert(field.name).second) badField(where, field.name, "the name is repeated");
    const auto [low, high] = rowRange(field.kind);
    if (values.rows() < low || values.rows() > high)
      badField(where, field.name,
               std::to_string(values.rows()) + " components, expected " +
                   (low == high ? std::to_string(low) : std::to_string(low) + " to " + std::to_string(high)));
    if (values.cols() != columns)
      badField(where, field.name,
               std::to_string(values.cols()) + " columns, the mesh has " + std::to_string(columns) + " " + columnName);
    for (Eigen::Index j = 0; j < values.cols(); ++j)
      for (Eigen::Index i = 0; i < values.rows(); ++i)
        if (!storable(values(i, j), field.kind, precision))
          badField(where, field.name, valueProblem(values(i, j), field.kind) + " at column " + std::to_string(j));
  }
}

/// The raw bytes (native byte order) of `count` values value(k) stored as T.
template <typename T, typename ValueAt>
std::string rawValues(Eigen::Index count, ValueAt value) {
  std::string bytes(static_cast<std::size_t>(count) * sizeof(T), '\0');
  for (Eigen::Index k = 0; k < count; ++k) {
    const T stored = static_cast<T>(value(k));
    std::memcpy(bytes.data() + static_cast<std::size_t>(k) * sizeof(T), &stored, sizeof(T));
  }
  return bytes;
}

/// `values` (rows = components, cols = tuples) as a floating-point array of `components` per tuple;
/// rows beyond those of `values` are written as 0.
EncodedArray realArray(const std::string& name, const Eigen::Ref<const Eigen::MatrixXd>& values, int components,
                       const std::vector<std::string>& names, FieldPrecision precision) {
  const auto valueAt = [&](Eigen::Index k) {
    const Eigen::Index i = k % components, j = k / components;
    return i < values.rows() ? values(i, j) : 0.0;
  };
  const Eigen::Index count = components * values.cols();
  if (precision == FieldPrecision::Float32)
    return {"Float32", name, components, names, vtkZlibBlocks(rawValues<float>(count, valueAt))};
  return {"Float64", name, components, names, vtkZlibBlocks(rawValues<double>(count, valueAt))};
}

/// An id array (connectivity or offsets) of `count` values value(k), the largest `largest`.
template <typename ValueAt>
EncodedArray idArray(const char* name, Eigen::Index count, long long largest, ValueAt value) {
  const std::string type = vtkIdTypeFor(largest);
  return {type, name, 1, {},
          vtkZlibBlocks(type == "Int32" ? rawValues<std::int32_t>(count, value) : rawValues<std::int64_t>(count, value))};
}

}  // namespace

void checkFields(const std::vector<PointField>& fields, Eigen::Index columns, FieldPrecision precision) {
  checkFieldsOf(fields, "point", columns, "nodes", precision);
}

void checkFields(const std::vector<CellField>& fields, Eigen::Index columns, FieldPrecision precision) {
  checkFieldsOf(fields, "cell", columns, "elements", precision);
}

int storedComponents(FieldKind kind, Eigen::Index rows) {
  if (kind == FieldKind::SymmetricTensor) return 6;
  return rows == 1 ? 1 : 3;
}

EncodedArray encodedField(const std::string& name, const Eigen::MatrixXd& values, FieldKind kind,
                          FieldPrecision precision) {
  if (kind == FieldKind::Code)
    return {"Int8", name, 1, {},
            vtkZlibBlocks(rawValues<std::int8_t>(values.cols(), [&](Eigen::Index j) { return values(0, j); }))};
  return realArray(name, values, storedComponents(kind, values.rows()), componentNames(kind, values.rows()),
                   precision);
}

EncodedArray pointArray(const Eigen::Ref<const Eigen::MatrixXd>& nodes, FieldPrecision precision) {
  for (Eigen::Index j = 0; j < nodes.cols(); ++j)
    for (Eigen::Index i = 0; i < nodes.rows(); ++i)
      if (!storable(nodes(i, j), FieldKind::Real, precision))
        throw std::invalid_argument("VTU points: " + valueProblem(nodes(i, j), FieldKind::Real) + " at node " +
                                    std::to_string(j));
  return realArray("Points", nodes, 3, {}, precision);
}

std::vector<EncodedArray> cellArrays(const Eigen::Ref<const Eigen::MatrixXi>& cells, Eigen::Index points, int vtkType) {
  const Eigen::Index n = cells.cols(), k = cells.rows();
  return {idArray("connectivity", k * n, points - 1, [&](Eigen::Index j) { return cells(j % k, j / k); }),
          idArray("offsets", n, k * n, [k](Eigen::Index e) { return k * (e + 1); }),
          {"UInt8", "types", 1, {}, vtkZlibBlocks(rawValues<std::uint8_t>(n, [vtkType](Eigen::Index) { return vtkType; }))}};
}

const char* vtkIdTypeFor(long long largest) {
  return largest <= std::numeric_limits<std::int32_t>::max() ? "Int32" : "Int64";
}

}  // namespace stc
