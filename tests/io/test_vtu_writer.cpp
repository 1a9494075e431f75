// ParaView output: well-formed XML (checked here and by python3's parser), the exact cell
// arrays of a two-triangle mesh, as many values per DataArray as its header promises, and
// collections that list their frames in order.
#include "stcontact/io/vtu_writer.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>
#include <regex>
#include <sstream>

#include "io/scratch_dir.hpp"
#include "mesh/two_tets.hpp"

namespace stc {
namespace {

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

struct DataArray {
  std::map<std::string, std::string> attributes;
  std::vector<std::string> values;  ///< the whitespace-separated words of its content
};

/// The DataArrays inside the first <section ...>...</section> of `document`, in order.
std::vector<DataArray> dataArraysIn(const std::string& document, const std::string& section) {
  const std::size_t begin = document.find("<" + section);
  const std::size_t end = document.find("</" + section + ">");
  if (begin == std::string::npos || end == std::string::npos) return {};
  const std::string body = document.substr(begin, end - begin);
  const std::regex arrayPattern(R"(<DataArray([^>]*)>([^<]*)</DataArray>)");
  const std::regex attributePattern(R"re((\w+)="([^"]*)")re");
  std::vector<DataArray> arrays;
  for (std::sregex_iterator it(body.begin(), body.end(), arrayPattern), last; it != last; ++it) {
    DataArray array;
    const std::string header = (*it)[1];
    for (std::sregex_iterator a(header.begin(), header.end(), attributePattern); a != last; ++a)
      array.attributes[(*a)[1]] = (*a)[2];
    std::istringstream words((*it)[2].str());
    for (std::string word; words >> word;) array.values.push_back(word);
    arrays.push_back(array);
  }
  return arrays;
}

/// The words of the DataArray called `name` in `section`, joined by single spaces.
std::string arrayText(const std::string& document, const std::string& section,
                      const std::string& name) {
  for (const DataArray& array : dataArraysIn(document, section))
    if (array.attributes.count("Name") && array.attributes.at("Name") == name) {
      std::string text;
      for (const std::string& word : array.values) text += (text.empty() ? "" : " ") + word;
      return text;
    }
  ADD_FAILURE() << "no DataArray '" << name << "' in <" << section << ">";
  return {};
}

/// Displacement (2 components), a nodal scalar and a three-component element field.
std::string sampleDocument() {
  const TriMesh mesh = unitSquare();
  Eigen::MatrixXd displacement(2, 4);
  displacement << 0.1, 0.2, 0.3, 0.4,  //
      -1, -2, -3, -4;
  Eigen::MatrixXd stress(3, 2);
  stress << 1, 2,  //
      3, 4,        //
      5, 6;
  return vtuDocument(mesh,
                     {{"displacement", displacement}, {"gap", Eigen::RowVector4d(0, 1, 2, 3)}},
                     {{"stress", stress}});
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

TEST(VtuDocument, IsWellFormedXml) {
  EXPECT_EQ(xmlStructureProblem(sampleDocument()), "");
  EXPECT_EQ(xmlStructureProblem(vtuDocument(unitSquare(), {}, {})), "");
}

TEST(VtuDocument, ParsesWithPythonXmlParser) {
  iotest::ScratchDir dir;
  iotest::writePlainFile(dir / "frame.vtu", sampleDocument());
  const int status = iotest::runPython(
      "import sys, xml.etree.ElementTree as E; r = E.parse(sys.argv[1]).getroot(); "
      "assert r.tag == \"VTKFile\" and len(r.findall(\".//DataArray\")) == 7",
      {dir / "frame.vtu"});
  if (status == iotest::kNoPython) GTEST_SKIP() << "python3 not available";
  EXPECT_EQ(status, 0);
}

TEST(VtuDocument, HasExactConnectivityOffsetsAndTypes) {
  const std::string document = sampleDocument();
  EXPECT_EQ(arrayText(document, "Cells", "connectivity"), "0 1 2 0 2 3");
  EXPECT_EQ(arrayText(document, "Cells", "offsets"), "3 6");
  EXPECT_EQ(arrayText(document, "Cells", "types"), "5 5");
  EXPECT_NE(document.find("<Piece NumberOfPoints=\"4\" NumberOfCells=\"2\">"), std::string::npos);
}

TEST(VtuDocument, WritesPointsInThePlaneZEqualsZero) {
  EXPECT_EQ(arrayText(sampleDocument(), "Points", "Points"), "0 0 0 1 0 0 1 1 0 0 1 0");
}

TEST(VtuDocument, EveryDataArrayHoldsComponentsTimesTuplesValues) {
  const std::string document = sampleDocument();
  const std::map<std::string, std::size_t> tuples = {
      {"PointData", 4}, {"CellData", 2}, {"Points", 4}};
  for (const auto& [section, count] : tuples) {
    const auto arrays = dataArraysIn(document, section);
    EXPECT_FALSE(arrays.empty()) << section;
    for (const DataArray& array : arrays) {
      const std::size_t components = std::stoul(array.attributes.at("NumberOfComponents"));
      EXPECT_EQ(array.values.size(), components * count) << array.attributes.at("Name");
    }
  }
  EXPECT_EQ(dataArraysIn(document, "Cells").size(), 3u);
}

TEST(VtuDocument, PadsPlaneVectorsWithZeroZ) {
  const std::string document = sampleDocument();
  EXPECT_EQ(arrayText(document, "PointData", "displacement"),
            "0.1 -1 0 0.2 -2 0 0.3 -3 0 0.4 -4 0");
  EXPECT_NE(document.find("Name=\"displacement\" NumberOfComponents=\"3\""), std::string::npos);
  EXPECT_NE(document.find("<PointData Scalars=\"gap\" Vectors=\"displacement\">"),
            std::string::npos);
}

TEST(VtuDocument, WritesScalarAndCellFieldsAsGiven) {
  const std::string document = sampleDocument();
  EXPECT_EQ(arrayText(document, "PointData", "gap"), "0 1 2 3");
  EXPECT_EQ(arrayText(document, "CellData", "stress"), "1 3 5 2 4 6");
}

TEST(VtuDocument, KeepsTenSignificantDigits) {
  const TriMesh mesh = unitSquare();
  const Eigen::RowVector4d values(1.0 / 3.0, -2e-9 / 3.0, 12345.678901234, 1e300);
  const std::string text = arrayText(vtuDocument(mesh, {{"f", values}}, {}), "PointData", "f");
  EXPECT_EQ(text, "0.3333333333 -6.666666667e-10 12345.6789 1e+300");
  std::istringstream words(text);
  for (int i = 0; i < 4; ++i) {
    double back = 0;
    words >> back;
    EXPECT_NEAR(back, values(i), 5e-10 * std::abs(values(i)));
  }
}

TEST(VtuDocument, EscapesXmlSpecialCharactersInFieldNames) {
  const std::string document =
      vtuDocument(unitSquare(), {{"a<b & \"c\"", Eigen::RowVector4d::Zero()}}, {});
  EXPECT_NE(document.find("Name=\"a&lt;b &amp; &quot;c&quot;\""), std::string::npos);
  EXPECT_EQ(xmlStructureProblem(document), "");
}

TEST(VtuDocument, RejectsAFieldWithTheWrongNumberOfColumnsNamingIt) {
  const TriMesh mesh = unitSquare();
  std::string message = invalidArgumentOf([&] {
    vtuDocument(mesh, {{"displacement", Eigen::MatrixXd::Zero(2, 5)}}, {});
  });
  EXPECT_NE(message.find("'displacement'"), std::string::npos) << message;
  message = invalidArgumentOf([&] {
    vtuDocument(mesh, {}, {{"stress", Eigen::MatrixXd::Zero(3, 4)}});
  });
  EXPECT_NE(message.find("'stress'"), std::string::npos) << message;
}

TEST(VtuDocument, RejectsPointFieldsWithoutOneToThreeComponents) {
  const TriMesh mesh = unitSquare();
  for (int rows : {0, 4}) {
    const std::string message = invalidArgumentOf([&] {
      vtuDocument(mesh, {{"tensor", Eigen::MatrixXd::Zero(rows, 4)}}, {});
    });
    EXPECT_NE(message.find("'tensor'"), std::string::npos) << message;
  }
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
  Eigen::MatrixXd values = Eigen::MatrixXd::Zero(1, 4);
  values(0, 2) = std::numeric_limits<double>::quiet_NaN();
  std::ostringstream out;
  const std::string message = invalidArgumentOf([&] {
    writeVtu(out, unitSquare(), {{"pressure", values}}, {});
  });
  EXPECT_NE(message.find("'pressure'"), std::string::npos) << message;
  EXPECT_EQ(out.str(), "");
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

TEST(PvdDocument, RejectsEmptyFileNamesAndNonFiniteTimes) {
  EXPECT_THROW(pvdDocument({{0.0, ""}}), std::invalid_argument);
  EXPECT_THROW(pvdDocument({{std::numeric_limits<double>::quiet_NaN(), "a.vtu"}}),
               std::invalid_argument);
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
  EXPECT_TRUE(xmlStructureProblem(document).empty()) << xmlStructureProblem(document);
  EXPECT_EQ(arrayText(document, "Cells", "connectivity"), "0 1 2 3 0 2 4 3");
  EXPECT_EQ(arrayText(document, "Cells", "offsets"), "4 8");
  EXPECT_EQ(arrayText(document, "Cells", "types"), "10 10");
  EXPECT_EQ(arrayText(document, "Points", "Points"), "0 0 0 1 0 0 0 1 0 0 0 1 -1 0 0");
  EXPECT_NE(document.find("<Piece NumberOfPoints=\"5\" NumberOfCells=\"2\">"), std::string::npos);
}

TEST(VtuTetDocument, RejectsAFieldWithTheWrongNumberOfColumnsNamingIt) {
  EXPECT_THROW(vtuDocument(twoTets(), {{"displacement", Eigen::MatrixXd::Zero(3, 4)}}, {}),
               std::invalid_argument);
  EXPECT_THROW(vtuDocument(twoTets(), {}, {{"stress", Eigen::MatrixXd::Zero(6, 3)}}), std::invalid_argument);
}

// A series writes every frame through one VtuGrid (the points and cells formatted once): each frame
// is the document writeVtu gives for its fields, and the checks still refuse a field of the wrong size.
TEST(VtuGrid, FramesAreTheDocumentsOfWriteVtu) {
  const TriMesh mesh = unitSquare();
  const VtuGrid grid(mesh);
  for (double scale : {1.0, -2.5e-7}) {
    const Eigen::MatrixXd displacement = scale * Eigen::MatrixXd::Random(2, 4);
    const Eigen::MatrixXd stress = scale * Eigen::MatrixXd::Random(3, 2);
    std::ostringstream frame;
    grid.write(frame, {{"displacement", displacement}}, {{"stress", stress}});
    EXPECT_EQ(frame.str(), vtuDocument(mesh, {{"displacement", displacement}}, {{"stress", stress}}));
  }
  std::ostringstream ignored;
  const std::string message =
      invalidArgumentOf([&] { grid.write(ignored, {{"gap", Eigen::RowVector3d(0, 1, 2)}}, {}); });
  EXPECT_NE(message.find("3 columns, the mesh has 4 nodes"), std::string::npos) << message;
  EXPECT_TRUE(ignored.str().empty());
}

}  // namespace stc
