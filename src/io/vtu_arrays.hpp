#pragma once
// The arrays of a .vtu document (vtu_writer.hpp): the fields and the mesh checked, converted to their
// VTK types and compressed (vtk_zlib_blocks.hpp), each with the attributes of its DataArray element.
// Types: floating-point values Float32 or Float64 (FieldPrecision), codes Int8, connectivity and offsets
// Int32 when their largest value fits and Int64 otherwise, cell types UInt8. Component names
// (ComponentName0…): vectors X, Y, Z; symmetric tensors XX, YY, ZZ, XY, YZ, XZ, the order of VTK's
// six-component tensors (vtkMath::TensorFromSymmetricTensor).
#include <Eigen/Core>
#include <string>
#include <vector>

#include "stcontact/scene/output_spec.hpp"

namespace stc {

/// What the rows of a field are: they set the stored type and the names of the components.
enum class FieldKind {
  Real,             ///< 1 row (a scalar) or 2–3 rows (a vector, written as X, Y, Z; z = 0 for 2 rows)
  Code,             ///< 1 row of integers in [−128, 127] (e.g. a state code), written as Int8
  SymmetricTensor,  ///< 6 rows in VTK's order xx, yy, zz, xy, yz, xz, written as XX, YY, ZZ, XY, YZ, XZ
};

/// Nodal values: one column per node.
struct PointField {
  std::string name;
  Eigen::MatrixXd values;
  FieldKind kind = FieldKind::Real;
};

/// Element values: one column per element.
struct CellField {
  std::string name;
  Eigen::MatrixXd values;
  FieldKind kind = FieldKind::Real;
};

/// One DataArray: its attributes and its data, compressed.
struct EncodedArray {
  std::string type;                         ///< "Float32", "Int8", …
  std::string name;
  int components = 1;
  std::vector<std::string> componentNames;  ///< empty, or one per component
  std::string blocks;                       ///< vtkZlibBlocks of the raw values
};

/// Throws std::invalid_argument naming the field if a name is empty or repeated, the columns are not
/// `columns` (the mesh's nodes or elements), the rows are not the kind's, a value is NaN or infinite,
/// a code is not an Int8 integer, or (Float32) a value lies beyond float's range.
void checkFields(const std::vector<PointField>& fields, Eigen::Index columns, FieldPrecision precision);
void checkFields(const std::vector<CellField>& fields, Eigen::Index columns, FieldPrecision precision);

/// Components written for a field of this kind with `rows` rows (a plane vector gets z = 0).
int storedComponents(FieldKind kind, Eigen::Index rows);

/// A checked field, converted and compressed.
EncodedArray encodedField(const std::string& name, const Eigen::MatrixXd& values, FieldKind kind,
                          FieldPrecision precision);

/// The points (2 or 3 rows; z = 0 for 2). Throws std::invalid_argument for a point that is not
/// finite or (Float32) lies beyond float's range.
EncodedArray pointArray(const Eigen::Ref<const Eigen::MatrixXd>& nodes, FieldPrecision precision);

/// connectivity, offsets and types of cells of one VTK type (`cells`: the node ids of each, one
/// column per cell, ids below `points`).
std::vector<EncodedArray> cellArrays(const Eigen::Ref<const Eigen::MatrixXi>& cells, Eigen::Index points, int vtkType);

/// The type of connectivity or offsets whose largest value is `largest`: "Int32" when it fits, else
/// "Int64".
const char* vtkIdTypeFor(long long largest);

}  // namespace stc
