// ParaView output, read back through tests/io/vtu_reading.hpp: well-formed XML once the appended
// bytes are set aside (checked here and by python3's parser), the exact cell arrays of a two-triangle
// mesh in their integer types, values in the precision asked, component names and VTK's tensor
// order, arrays back to back in the appended data, and collections that list their frames in order.
#include "stcontact/io/vtu_writer.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <regex>
#include <sstream>

#include "io/scratch_dir.hpp"
#include "io/vtu_reading.hpp"
#include "mesh/two_tets.hpp"

namespace stc {
namespace {

using iotest::readVtu;
using iotest::VtuFile;

/// The unit square split along its diagonal: triangles (0 1 2) and (0 2 3).
TriMesh unitSquare() {
  TriMesh mesh;
  mesh.nodes.resize(2, 4);
  mesh.nodes << 0, 1, 1, 0,  //
      0, 0, 1, 1;
  mesh.triangles.resize(3, 2);
  mesh.triangles << 0, 0,  //
      1, 2,                //
      2, 3;
  return mesh;
}

/// Empty if every element is closed in order, quotes pair up in every tag and there is exactly
/// one root element; otherwise what is wrong. A structural check, not a full XML parser.
std::string xmlStructureProblem(const std::string& document) {
  std::vector<std::string> open;
  int roots = 0;
  for (std::size_t pos = document.find('<'); pos != std::string::npos;
       pos = document.find('<', pos)) {
    const std::size_t end = document.find('>', pos);
    if (end == std::string::npos) return "unterminated tag at offset " + std::to_string(pos);
    const std::string tag = document.substr(pos + 1, end - pos - 1);
    pos = end + 1;
    if (tag.empty()) return "empty tag";
    if (tag.front() == '?') continue;  // the XML declaration
    if (std::count(tag.begin(), tag.end(), '"') % 2 != 0) return "odd quotes in <" + tag + ">";
    if (tag.front() == '/') {
      if (open.empty() || open.back() != tag.substr(1))
        return "<" + tag + "> closes " + (open.empty() ? "nothing" : "<" + open.back() + ">");
      open.pop_back();
      continue;
    }
    if (open.empty()) ++roots;
    if (tag.back() != '/') open.push_back(tag.substr(0, tag.find_first_of(" \t\n")));
  }
  if (!open.empty()) return "<" + open.back() + "> is never closed";
  if (roots != 1) return std::to_string(roots) + " root elements";
  return {};
}

/// `values` rounded to float, as Float32 arrays hold them.
std::vector<double> asFloat32(const std::vector<double>& values) {
  std::vector<double> rounded;
  for (double v : values) rounded.push_back(static_cast<float>(v));
  return rounded;
}

/// The state codes of the sample: −1 (not a contact node), 0, 1, 2.
const Eigen::RowVector4d kStates(-1, 0, 1, 2);

/// Displacement (2 components), a nodal scalar and code, an element tensor and scalar.
std::string sampleDocument(FieldPrecision precision = FieldPrecision::Float32) {
  Eigen::MatrixXd displacement(2, 4);
  displacement << 0.1, 0.2, 0.3, 0.4,  //
      -1, -2, -3, -4;
  Eigen::MatrixXd stress(6, 2);  // xx, yy, zz, xy, yz, xz
  stress << 11, 21,  //
      12, 22,        //
      13, 23,        //
      14, 24,        //
      15, 25,        //
      16, 26;
  return vtuDocument(unitSquare(),
                     {{"displacement", displacement},
                      {"gap", Eigen::RowVector4d(0, 1, 2, 3)},
                      {"state", kStates, FieldKind::Code}},
                     {{"stress", stress, FieldKind::SymmetricTensor}, {"von_mises", Eigen::RowVector2d(7, 8)}},
                     precision);
}

/// The std::invalid_argument message of `action`, or a test failure if none is thrown.
template <typename Action>
std::string invalidArgumentOf(Action action) {
  try {
    action();
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
  ADD_FAILURE() << "no std::invalid_argument thrown";
  return {};
}

TEST(VtuDocument, IsWellFormedXmlOnceTheAppendedBytesAreSetAside) {
  EXPECT_EQ(xmlStructureProblem(readVtu(sampleDocument()).xml), "");
  EXPECT_EQ(xmlStructureProblem(readVtu(vtuDocument(unitSquare(), {}, {})).xml), "");
}

TEST(VtuDocument, DeclaresCompressedAppendedDataWithUInt64Headers) {
  const std::string document = sampleDocument();
  EXPECT_NE(document.find("<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
                          "header_type=\"UInt64\" compressor=\"vtkZLibDataCompressor\">"),
            std::string::npos);
  EXPECT_NE(document.find("<AppendedData encoding=\"raw\">\n   _"), std::string::npos);
  for (const auto& [section, arrays] : readVtu(document).sections)
    for (const auto& array : arrays) EXPECT_EQ(array.attributes.at("format"), "appended") << array.attributes.at("Name");
}

TEST(VtuDocument, ParsesWithPythonXmlParser) {
  iotest::ScratchDir dir;
  iotest::writePlainFile(dir / "frame.xml", readVtu(sampleDocument()).xml);
  const int status = iotest::runPython(
      "import sys, xml.etree.ElementTree as E; r = E.parse(sys.argv[1]).getroot(); "
      "assert r.tag == \"VTKFile\" and len(r.findall(\".//DataArray\")) == 9",
      {dir / "frame.xml"});
  if (status == iotest::kNoPython) GTEST_SKIP() << "python3 not available";
  EXPECT_EQ(status, 0);
}

TEST(VtuDocument, HasExactConnectivityOffsetsAndTypesAsIntegers) {
  const std::string document = sampleDocument();
  const VtuFile file = readVtu(document);
  EXPECT_EQ(file.array("Cells", "connectivity").values, (std::vector<double>{0, 1, 2, 0, 2, 3}));
  EXPECT_EQ(file.array("Cells", "offsets").values, (std::vector<double>{3, 6}));
  EXPECT_EQ(file.array("Cells", "types").values, (std::vector<double>{5, 5}));
  EXPECT_EQ(file.array("Cells", "connectivity").attributes.at("type"), "Int32");
  EXPECT_EQ(file.array("Cells", "offsets").attributes.at("type"), "Int32");
  EXPECT_EQ(file.array("Cells", "types").attributes.at("type"), "UInt8");
  EXPECT_NE(document.find("<Piece NumberOfPoints=\"4\" NumberOfCells=\"2\">"), std::string::npos);
}

TEST(VtuDocument, IdsAreInt32UpToItsLargestValueThenInt64) {
  EXPECT_STREQ(vtkIdTypeFor(0), "Int32");
  EXPECT_STREQ(vtkIdTypeFor(2147483647LL), "Int32");
  EXPECT_STREQ(vtkIdTypeFor(2147483648LL), "Int64");
}

TEST(VtuDocument, WritesPointsInThePlaneZEqualsZero) {
  EXPECT_EQ(readVtu(sampleDocument()).array("Points", "Points").values,
            (std::vector<double>{0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0}));
}

TEST(VtuDocument, EveryDataArrayHoldsComponentsTimesTuplesValues) {
  const VtuFile file = readVtu(sampleDocument());
  const std::map<std::string, std::size_t> tuples = {{"PointData", 4}, {"CellData", 2}, {"Points", 4}};
  for (const auto& [section, count] : tuples) {
    ASSERT_TRUE(file.sections.count(section)) << section;
    for (const auto& array : file.sections.at(section)) {
      const std::size_t components = std::stoul(array.attributes.at("NumberOfComponents"));
      EXPECT_EQ(array.values.size(), components * count) << array.attributes.at("Name");
    }
  }
  EXPECT_EQ(file.sections.at("Cells").size(), 3u);
}

TEST(VtuDocument, ArraysLieBackToBackAndFillTheAppendedData) {
  const std::string document = sampleDocument();
  std::vector<std::pair<std::uint64_t, std::uint64_t>> spans;  // [offset, end) of each array
  for (const auto& [section, arrays] : readVtu(document).sections)
    for (const auto& array : arrays) spans.emplace_back(std::stoull(array.attributes.at("offset")), array.end);
  std::sort(spans.begin(), spans.end());
  ASSERT_EQ(spans.size(), 9u);
  EXPECT_EQ(spans.front().first, 0u);
  for (std::size_t i = 1; i < spans.size(); ++i) EXPECT_EQ(spans[i].first, spans[i - 1].second);
  EXPECT_EQ(spans.back().second, iotest::appendedSize(document));
}

// Reverse order keeps meshio's raw reader, which finds arrays by the text of their offsets while it
// rewrites them, from taking one array for another (src/io/vtu_writer.hpp).
TEST(VtuDocument, AppendedDataHoldsTheArraysInReverseXmlOrder) {
  const std::string document = sampleDocument();
  const std::string header = document.substr(0, document.find("<AppendedData"));
  const std::regex offset(R"re(offset="([0-9]+)")re");
  std::vector<long long> offsets;
  for (std::sregex_iterator it(header.begin(), header.end(), offset), last; it != last; ++it)
    offsets.push_back(std::stoll((*it)[1]));
  ASSERT_EQ(offsets.size(), 9u);
  for (std::size_t i = 1; i < offsets.size(); ++i) EXPECT_GT(offsets[i - 1], offsets[i]) << i;
  EXPECT_EQ(offsets.back(), 0);
}

TEST(VtuDocument, PadsPlaneVectorsWithZeroZAndNamesTheirComponents) {
  const std::string document = sampleDocument();
  const VtuFile file = readVtu(document);
  const auto& displacement = file.array("PointData", "displacement");
  EXPECT_EQ(displacement.values, asFloat32({0.1, -1, 0, 0.2, -2, 0, 0.3, -3, 0, 0.4, -4, 0}));
  EXPECT_EQ(displacement.attributes.at("NumberOfComponents"), "3");
  EXPECT_EQ(displacement.attributes.at("ComponentName0"), "X");
  EXPECT_EQ(displacement.attributes.at("ComponentName1"), "Y");
  EXPECT_EQ(displacement.attributes.at("ComponentName2"), "Z");
  EXPECT_NE(document.find("<PointData Scalars=\"gap\" Vectors=\"displacement\">"), std::string::npos);
}

TEST(VtuDocument, WritesSymmetricTensorsInVtkOrderWithTheirNames) {
  const std::string document = sampleDocument();
  const VtuFile file = readVtu(document);
  const auto& stress = file.array("CellData", "stress");
  EXPECT_EQ(stress.values, (std::vector<double>{11, 12, 13, 14, 15, 16, 21, 22, 23, 24, 25, 26}));
  EXPECT_EQ(stress.attributes.at("NumberOfComponents"), "6");
  const char* names[] = {"XX", "YY", "ZZ", "XY", "YZ", "XZ"};
  for (int i = 0; i < 6; ++i) EXPECT_EQ(stress.attributes.at("ComponentName" + std::to_string(i)), names[i]);
  EXPECT_NE(document.find("<CellData Scalars=\"von_mises\" Tensors=\"stress\">"), std::string::npos);
}

TEST(VtuDocument, WritesCodesAsInt8AndScalarsWithoutComponentNames) {
  const VtuFile file = readVtu(sampleDocument());
  const auto& state = file.array("PointData", "state");
  EXPECT_EQ(state.attributes.at("type"), "Int8");
  EXPECT_EQ(state.values, (std::vector<double>{-1, 0, 1, 2}));
  const auto& gap = file.array("PointData", "gap");
  EXPECT_EQ(gap.attributes.at("type"), "Float32");
  EXPECT_EQ(gap.values, (std::vector<double>{0, 1, 2, 3}));
  EXPECT_EQ(gap.attributes.count("ComponentName0"), 0u);
}

TEST(VtuDocument, Float64KeepsEveryBitAndFloat32RoundsToNearest) {
  const Eigen::RowVector4d values(1.0 / 3.0, -2e-9 / 3.0, 12345.678901234, 1e300);
  const VtuFile exact = readVtu(vtuDocument(unitSquare(), {{"f", values}}, {}, FieldPrecision::Float64));
  EXPECT_EQ(exact.array("PointData", "f").attributes.at("type"), "Float64");
  EXPECT_EQ(exact.array("PointData", "f").values, (std::vector<double>(values.data(), values.data() + 4)));
  EXPECT_EQ(exact.array("Points", "Points").attributes.at("type"), "Float64");
  const Eigen::RowVector4d small = values.cwiseMin(1e30);
  const VtuFile rounded = readVtu(vtuDocument(unitSquare(), {{"f", small}}, {}));
  EXPECT_EQ(rounded.array("PointData", "f").attributes.at("type"), "Float32");
  EXPECT_EQ(rounded.array("PointData", "f").values, asFloat32({small[0], small[1], small[2], small[3]}));
}

TEST(VtuDocument, RefusesValuesBeyondFloat32NamingTheFieldAndTheWayOut) {
  const Eigen::RowVector4d values(0, 1, 1e39, 3);
  const std::string message = invalidArgumentOf([&] { vtuDocument(unitSquare(), {{"pressure", values}}, {}); });
  EXPECT_NE(message.find("'pressure'"), std::string::npos) << message;
  EXPECT_NE(message.find("Float32"), std::string::npos) << message;
  EXPECT_NE(message.find("column 2"), std::string::npos) << message;
  EXPECT_NE(message.find("float64"), std::string::npos) << message;
  EXPECT_NO_THROW(vtuDocument(unitSquare(), {{"pressure", values}}, {}, FieldPrecision::Float64));
}

TEST(VtuDocument, RefusesCodesThatAreNotInt8Integers) {
  for (double bad : {0.5, 128.0, -129.0}) {
    const Eigen::RowVector4d values(0, bad, 1, 2);
    const std::string message =
        invalidArgumentOf([&] { vtuDocument(unitSquare(), {{"state", values, FieldKind::Code}}, {}); });
    EXPECT_NE(message.find("'state'"), std::string::npos) << message;
    EXPECT_NE(message.find("Int8"), std::string::npos) << message;
  }
}

TEST(VtuDocument, EscapesXmlSpecialCharactersInFieldNames) {
  const std::string document =
      vtuDocument(unitSquare(), {{"a<b & \"c\"", Eigen::RowVector4d::Zero()}}, {});
  EXPECT_NE(document.find("Name=\"a&lt;b &amp; &quot;c&quot;\""), std::string::npos);
  EXPECT_EQ(xmlStructureProblem(readVtu(document).xml), "");
}

TEST(VtuDocument, RejectsAFieldWithTheWrongNumberOfColumnsNamingIt) {
  const TriMesh mesh = unitSquare();
  std::string message = invalidArgumentOf([&] {
    vtuDocument(mesh, {{"displacement", Eigen::MatrixXd::Zero(2, 5)}}, {});
  });
  EXPECT_NE(message.find("'displacement'"), std::string::npos) << message;
  message = invalidArgumentOf([&] {
    vtuDocument(mesh, {}, {{"stress", Eigen::MatrixXd::Zero(6, 4), FieldKind::SymmetricTensor}});
  });
  EXPECT_NE(message.find("'stress'"), std::string::npos) << message;
}

TEST(VtuDocument, RejectsRowCountsTheKindDoesNotHave) {
  const TriMesh mesh = unitSquare();
  for (int rows : {0, 4}) {
    const std::string message = invalidArgumentOf([&] {
      vtuDocument(mesh, {{"tensor", Eigen::MatrixXd::Zero(rows, 4)}}, {});
    });
    EXPECT_NE(message.find("'tensor'"), std::string::npos) << message;
  }
  const std::string message = invalidArgumentOf(
      [&] { vtuDocument(mesh, {}, {{"stress", Eigen::MatrixXd::Zero(3, 2), FieldKind::SymmetricTensor}}); });
  EXPECT_NE(message.find("3 components, expected 6"), std::string::npos) << message;
  EXPECT_THROW(vtuDocument(mesh, {{"state", Eigen::MatrixXd::Zero(2, 4), FieldKind::Code}}, {}),
               std::invalid_argument);
}

TEST(VtuDocument, RejectsEmptyAndRepeatedNames) {
  const TriMesh mesh = unitSquare();
  const Eigen::MatrixXd zero = Eigen::MatrixXd::Zero(1, 4);
  EXPECT_THROW(vtuDocument(mesh, {{"", zero}}, {}), std::invalid_argument);
  const std::string message = invalidArgumentOf([&] {
    vtuDocument(mesh, {{"u", zero}, {"u", zero}}, {});
  });
  EXPECT_NE(message.find("'u'"), std::string::npos) << message;
}

TEST(VtuDocument, RejectsNonFiniteValuesBeforeWritingAnything) {
  for (FieldPrecision precision : {FieldPrecision::Float32, FieldPrecision::Float64}) {
    Eigen::MatrixXd values = Eigen::MatrixXd::Zero(1, 4);
    values(0, 2) = std::numeric_limits<double>::quiet_NaN();
    std::ostringstream out;
    const std::string message = invalidArgumentOf([&] {
      writeVtu(out, unitSquare(), {{"pressure", values}}, {}, precision);
    });
    EXPECT_NE(message.find("'pressure'"), std::string::npos) << message;
    EXPECT_EQ(out.str(), "");
  }
}

TEST(VtuDocument, StreamedAndStringDocumentsAreIdentical) {
  const TriMesh mesh = unitSquare();
  const std::vector<PointField> fields = {{"gap", Eigen::RowVector4d(0, 1, 2, 3)}};
  std::ostringstream out;
  writeVtu(out, mesh, fields, {});
  EXPECT_EQ(out.str(), vtuDocument(mesh, fields, {}));
}

TEST(PvdDocument, ListsFramesInTheGivenOrderWithExactTimes) {
  const std::string document = pvdDocument({{0.0, "vtu/solution_000.vtu"},
                                            {0.1 + 0.2, "vtu/solution_001.vtu"},
                                            {1.0, "vtu/solution_002.vtu"}});
  EXPECT_EQ(xmlStructureProblem(document), "");
  const std::regex dataSet(R"re(<DataSet timestep="([^"]*)" group="" part="0" file="([^"]*)"/>)re");
  std::vector<std::string> times, files;
  for (std::sregex_iterator it(document.begin(), document.end(), dataSet), last; it != last; ++it) {
    times.push_back((*it)[1]);
    files.push_back((*it)[2]);
  }
  EXPECT_EQ(files, (std::vector<std::string>{"vtu/solution_000.vtu", "vtu/solution_001.vtu",
                                             "vtu/solution_002.vtu"}));
  ASSERT_EQ(times.size(), 3u);
  EXPECT_EQ(times[0], "0");
  EXPECT_EQ(std::strtod(times[1].c_str(), nullptr), 0.1 + 0.2);  // not rounded to 0.3
  EXPECT_EQ(times[2], "1");
  EXPECT_NE(document.find("<VTKFile type=\"Collection\""), std::string::npos);
}

TEST(PvdDocument, EmptyCollectionIsWellFormed) {
  EXPECT_EQ(xmlStructureProblem(pvdDocument({})), "");
}

TEST(PvdDocument, RejectsEmptyFileNamesNonFiniteTimesAndNegativeParts) {
  EXPECT_THROW(pvdDocument({{0.0, ""}}), std::invalid_argument);
  EXPECT_THROW(pvdDocument({{std::numeric_limits<double>::quiet_NaN(), "a.vtu"}}),
               std::invalid_argument);
  EXPECT_THROW(pvdDocument({{0.0, "a.vtu", -1}}), std::invalid_argument);
}

// Two bodies: the files of one time are parts 0 and 1, each named (the blocks ParaView shows).
TEST(PvdDocument, ListsThePartsOfOneTimeWithTheirNames) {
  const std::string document = pvdDocument({{0.5, "vtu/step_00001_body0.vtu", 0, "body 0"},
                                            {0.5, "vtu/step_00001_body1.vtu", 1, "body <1>"}});
  EXPECT_EQ(xmlStructureProblem(document), "");
  EXPECT_NE(document.find(R"(<DataSet timestep="0.5" group="" part="0" file="vtu/step_00001_body0.vtu" name="body 0"/>)"),
            std::string::npos);
  EXPECT_NE(document.find(R"(part="1" file="vtu/step_00001_body1.vtu" name="body &lt;1&gt;"/>)"), std::string::npos);
}

}  // namespace
}  // namespace stc

namespace stc {

using test::twoTets;

TEST(VtuTetDocument, HasTetraConnectivityOffsetsTypesAndThreeDimensionalPoints) {
  const TetMesh mesh = twoTets();
  ASSERT_GT(mesh.sixSignedVolume(0), 0.0);
  ASSERT_GT(mesh.sixSignedVolume(1), 0.0);
  Eigen::MatrixXd displacement(3, 5);
  displacement.setOnes();
  const std::string document =
      vtuDocument(mesh, {{"displacement", displacement}}, {{"von_mises", Eigen::MatrixXd::Constant(1, 2, 2.5)}});
  const iotest::VtuFile file = iotest::readVtu(document);
  EXPECT_TRUE(xmlStructureProblem(file.xml).empty()) << xmlStructureProblem(file.xml);
  EXPECT_EQ(file.array("Cells", "connectivity").values, (std::vector<double>{0, 1, 2, 3, 0, 2, 4, 3}));
  EXPECT_EQ(file.array("Cells", "offsets").values, (std::vector<double>{4, 8}));
  EXPECT_EQ(file.array("Cells", "types").values, (std::vector<double>{10, 10}));
  EXPECT_EQ(file.array("Points", "Points").values, (std::vector<double>{0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, -1, 0, 0}));
  EXPECT_EQ(file.array("CellData", "von_mises").values, (std::vector<double>{2.5, 2.5}));
  EXPECT_NE(document.find("<Piece NumberOfPoints=\"5\" NumberOfCells=\"2\">"), std::string::npos);
}

TEST(VtuTetDocument, RejectsAFieldWithTheWrongNumberOfColumnsNamingIt) {
  EXPECT_THROW(vtuDocument(twoTets(), {{"displacement", Eigen::MatrixXd::Zero(3, 4)}}, {}),
               std::invalid_argument);
  EXPECT_THROW(vtuDocument(twoTets(), {}, {{"stress", Eigen::MatrixXd::Zero(6, 3), FieldKind::SymmetricTensor}}),
               std::invalid_argument);
}

// A series writes every frame through one VtuGrid (the points and cells compressed once): each frame
// is the document writeVtu gives for its fields, and the checks still refuse a field of the wrong size.
TEST(VtuGrid, FramesAreTheDocumentsOfWriteVtu) {
  const TriMesh mesh = unitSquare();
  for (FieldPrecision precision : {FieldPrecision::Float32, FieldPrecision::Float64}) {
    const VtuGrid grid(mesh, precision);
    for (double scale : {1.0, -2.5e-7}) {
      const Eigen::MatrixXd displacement = scale * Eigen::MatrixXd::Random(2, 4);
      const Eigen::MatrixXd stress = scale * Eigen::MatrixXd::Random(6, 2);
      const std::vector<PointField> points{{"displacement", displacement}};
      const std::vector<CellField> cells{{"stress", stress, FieldKind::SymmetricTensor}};
      std::ostringstream frame;
      grid.write(frame, points, cells);
      EXPECT_EQ(frame.str(), vtuDocument(mesh, points, cells, precision));
    }
  }
  const VtuGrid grid(mesh);
  std::ostringstream ignored;
  const std::string message =
      invalidArgumentOf([&] { grid.write(ignored, {{"gap", Eigen::RowVector3d(0, 1, 2)}}, {}); });
  EXPECT_NE(message.find("3 columns, the mesh has 4 nodes"), std::string::npos) << message;
  EXPECT_TRUE(ignored.str().empty());
}

TEST(VtuGrid, RefusesPointsBeyondFloat32) {
  TriMesh mesh = unitSquare();
  mesh.nodes(0, 1) = 1e39;
  const std::string message = invalidArgumentOf([&] { VtuGrid grid(mesh); });
  EXPECT_NE(message.find("VTU points"), std::string::npos) << message;
  EXPECT_NO_THROW(VtuGrid(mesh, FieldPrecision::Float64));
}

}  // namespace stc
