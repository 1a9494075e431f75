// The summary.json builder (over nlohmann-json): member order, escaping, exact number round trips,
// null for what JSON cannot express, and documents an independent parser (python3's json) accepts.
#include "stcontact/io/json_writer.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <random>
#include <regex>

#include "io/scratch_dir.hpp"

namespace stc {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

TEST(JsonObject, KeepsTheOrderOfAdd) {
  JsonObject object;
  object.add("solver", "latin").add("iterations", 12).add("converged", true);
  EXPECT_EQ(object.str(0), R"({"solver":"latin","iterations":12,"converged":true})");
}

TEST(JsonObject, EscapesQuotesBackslashesAndControlCharacters) {
  EXPECT_EQ(jsonString("say \"hi\"\\"), R"("say \"hi\"\\")");
  EXPECT_EQ(jsonString("a\nb\tc\rd\be\ff"), R"("a\nb\tc\rd\be\ff")");
  EXPECT_EQ(jsonString(std::string("\x01\x1f\0", 3)), R"("\u0001\u001f\u0000")");
  EXPECT_EQ(jsonString("/ \x7f caf\xc3\xa9"), "\"/ \x7f caf\xc3\xa9\"");  // copied as is
}

TEST(JsonObject, EscapesKeys) {
  JsonObject object;
  object.add("a\"b", 1);
  EXPECT_EQ(object.str(0), R"({"a\"b":1})");
}

TEST(JsonObject, DoublesReadBackExactlyWithStrtod) {
  using limits = std::numeric_limits<double>;
  std::vector<double> values = {0.1,    1.0 / 3.0,     -2.5e-7,       1e21,
                                1e-300, 6.02214076e23, -0.0,          0.0,
                                3.0,    limits::max(), limits::min(), limits::denorm_min()};
  std::mt19937_64 random(20240601);
  std::uniform_real_distribution<double> exponent(-300.0, 300.0);
  for (int i = 0; i < 1000; ++i)
    values.push_back(std::pow(10.0, exponent(random)) * (i % 2 ? -1 : 1));
  for (double value : values) {
    const std::string text = jsonNumber(value);
    const double back = std::strtod(text.c_str(), nullptr);
    EXPECT_EQ(std::memcmp(&back, &value, sizeof value), 0) << text;  // bitwise: keeps -0
  }
}

TEST(JsonObject, NumbersFollowTheJsonGrammar) {
  const std::regex number(R"(-?(0|[1-9][0-9]*)(\.[0-9]+)?([eE][+-]?[0-9]+)?)");
  for (double value : {0.0, -0.0, 1.0, 0.5, 1e21, 1e-7, 123456.789, -4e-320, 1e300})
    EXPECT_TRUE(std::regex_match(jsonNumber(value), number)) << jsonNumber(value);
  EXPECT_EQ(jsonNumber(3.0), "3.0");  // a double stays a double
  EXPECT_EQ(jsonNumber(0.1), "0.1");
}

TEST(JsonObject, WritesNullForNaNAndInfinities) {
  JsonObject object;
  object.add("nan", kNaN).add("inf", kInf).add("minus_inf", -kInf);
  object.add("list", std::vector<double>{1.5, kNaN, -kInf});
  EXPECT_EQ(object.str(0),
            R"({"nan":null,"inf":null,"minus_inf":null,"list":[1.5,null,null]})");
}

TEST(JsonObject, WritesIntegersBoolsAndNullsExactly) {
  JsonObject object;
  object.add("int", -7)
      .add("long", 1234567890123L)
      .add("max", std::numeric_limits<long long>::max());
  object.add("size", std::size_t{42}).add("yes", true).add("no", false).add("none", std::nullopt);
  EXPECT_EQ(object.str(0),
            R"({"int":-7,"long":1234567890123,"max":9223372036854775807,"size":42,)"
            R"("yes":true,"no":false,"none":null})");
}

TEST(JsonObject, WritesOptionalsAsValueOrNull) {
  JsonObject object;
  object.add("error", std::optional<double>{}).add("rank", std::optional<int>{3});
  object.add("name", std::optional<std::string>{"x"});
  EXPECT_EQ(object.str(0), R"({"error":null,"rank":3,"name":"x"})");
}

TEST(JsonObject, StringLiteralsAreStringsNotBools) {
  JsonObject object;
  const std::string owned = "owned";
  const char* none = nullptr;
  object.add("literal", "text").add("string", owned).add("none", none);
  EXPECT_EQ(object.str(0), R"({"literal":"text","string":"owned","none":null})");
}

TEST(JsonObject, RejectsARepeatedKey) {
  JsonObject object;
  object.add("iterations", 1);
  EXPECT_THROW(object.add("iterations", 2), std::invalid_argument);
}

TEST(JsonObject, EmptyObjectIsBraces) {
  EXPECT_EQ(JsonObject().str(), "{}\n");
  JsonObject outer;
  outer.add("inner", JsonObject());
  EXPECT_EQ(outer.str(0), R"({"inner":{}})");
}

TEST(JsonObject, IndentsNestedObjectsOneMemberPerLine) {
  JsonObject material;
  material.add("young", 3000.0).add("poisson", 0.3);
  JsonObject object;
  object.add("solver", "fas-apriori")
      .add("material", material)
      .add("times", std::vector<double>{0, 0.5});
  EXPECT_EQ(object.str(2),
            "{\n"
            "  \"solver\": \"fas-apriori\",\n"
            "  \"material\": {\n"
            "    \"young\": 3000.0,\n"
            "    \"poisson\": 0.3\n"
            "  },\n"
            "  \"times\": [\n"
            "    0.0,\n"
            "    0.5\n"
            "  ]\n"
            "}\n");
}

TEST(JsonObject, InsertsRawJsonAtItsDepthInItsOrder) {
  JsonObject object;
  object.add("parameters", RawJson{"{\n  \"name\": \"x\",\n  \"a\": [1, 2.5]\n}\n"});
  EXPECT_EQ(object.str(2),
            "{\n"
            "  \"parameters\": {\n"
            "    \"name\": \"x\",\n"
            "    \"a\": [\n"
            "      1,\n"
            "      2.5\n"
            "    ]\n"
            "  }\n"
            "}\n");
  EXPECT_EQ(object.str(0), R"({"parameters":{"name":"x","a":[1,2.5]}})");
}

TEST(JsonObject, RejectsEmptyOrInvalidRawJson) {
  JsonObject object;
  EXPECT_THROW(object.add("parameters", RawJson{" \n"}), std::invalid_argument);
  EXPECT_THROW(object.add("parameters", RawJson{"{\"a\": }"}), std::invalid_argument);
}

TEST(JsonObject, DocumentParsesWithPythonAndKeepsStringsAndNumbers) {
  iotest::ScratchDir dir;
  const std::string tricky = std::string("q\" b\\ nl\n tab\t ctl\x01 nul") + '\0' + "caf\xc3\xa9";
  JsonObject inner;
  inner.add("x", 0.1).add("nan", kNaN).add("list", std::vector<double>{1e-300, -0.0});
  JsonObject object;
  object.add("s", tricky).add("inner", inner).add("raw", RawJson{"{\"k\": [true, null]}"});
  iotest::writePlainFile(dir / "summary.json", object.str());
  // python3 writes back the string and repr of the numbers; both must match what we wrote.
  const std::string code =
      "import json, sys; d = json.load(open(sys.argv[1], encoding=\"utf-8\")); "
      "open(sys.argv[2], \"wb\").write(d[\"s\"].encode(\"utf-8\")); "
      "i = d[\"inner\"]; assert i[\"x\"] == 0.1 and i[\"nan\"] is None; "
      "assert i[\"list\"] == [1e-300, 0.0] and d[\"raw\"] == {\"k\": [True, None]}";
  const int status = iotest::runPython(code, {dir / "summary.json", dir / "s.bin"});
  if (status == iotest::kNoPython) GTEST_SKIP() << "python3 not available";
  ASSERT_EQ(status, 0);
  EXPECT_EQ(iotest::readFile(dir / "s.bin"), tricky);
}

}  // namespace
}  // namespace stc
