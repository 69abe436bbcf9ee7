#include "cairn/common/json_writer.h"

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "expect_throws.h"

namespace cairn {
namespace {

TEST(JsonWriterTest, WritesCairnsOneLineLayout) {
  JsonWriter json;
  json.BeginObject().Key("name").String("bars").Key("found").Bool(true).Key("reason").String("");
  json.Key("steps").Integer(std::size_t{3}).Key("none").Null().Key("list").BeginArray();
  json.Integer(1).Integer(-2).BeginObject().Key("x").Number(0.5).EndObject().BeginArray().EndArray().EndArray();
  json.Key("empty").BeginObject().EndObject().EndObject();
  EXPECT_TRUE(json.complete());
  EXPECT_EQ(json.text(),
            R"({"name": "bars", "found": true, "reason": "", "steps": 3, "none": null, "list": [1, -2, {"x": 0.5}, []], )"
            R"("empty": {}})");
}

TEST(JsonWriterTest, NumbersTakeTheirFormatAndNonFiniteIsNull) {
  JsonWriter json;
  json.BeginArray();
  json.Number(2.0, JsonWriter::Fixed(6)).Number(0.123456789, JsonWriter::Fixed(4)).Number(1.0 / 3.0);
  json.Number(1e-7).Number(123456789.0, JsonWriter::Significant(9)).Number(1.23456, JsonWriter::Significant(4));
  json.Number(std::numeric_limits<double>::quiet_NaN()).Number(std::numeric_limits<double>::infinity());
  json.Number(-std::numeric_limits<double>::infinity(), JsonWriter::Fixed(2)).Number(1e300, JsonWriter::Fixed(0));
  json.EndArray();
  const std::string& text = json.text();
  char huge[400];
  std::snprintf(huge, sizeof(huge), "%.0f", 1e300);  // 301 digits: no buffer of a fixed small size holds it
  EXPECT_EQ(text, std::string("[2.000000, 0.1235, 0.333333, 1e-07, 123456789, 1.235, null, null, null, ") + huge + "]");
  // Every document parses, and the non-finite numbers read back as null.
  const nlohmann::json parsed = nlohmann::json::parse(text);
  ASSERT_EQ(parsed.size(), 10u);
  EXPECT_TRUE(parsed[6].is_null());
  EXPECT_TRUE(parsed[7].is_null());
  EXPECT_TRUE(parsed[8].is_null());
  EXPECT_DOUBLE_EQ(parsed[9].get<double>(), 1e300);
  CAIRN_EXPECT_THROWS_WITH(JsonWriter::Significant(0), std::invalid_argument, "0 significant digits", "1 to 17");
  CAIRN_EXPECT_THROWS_WITH(JsonWriter::Fixed(18), std::invalid_argument, "18 decimals", "0 to 17");
}

TEST(JsonWriterTest, IntegersKeepEveryDigit) {
  JsonWriter json;
  json.BeginArray().Integer(std::numeric_limits<std::int64_t>::min()).Integer(std::numeric_limits<std::uint64_t>::max());
  json.Integer(static_cast<unsigned char>(200)).Integer(short{-3}).EndArray();
  EXPECT_EQ(json.text(), "[-9223372036854775808, 18446744073709551615, 200, -3]");
}

// Any text gives valid JSON: quotes, backslashes and control characters are escaped, invalid UTF-8 is replaced.
TEST(JsonWriterTest, EscapesEveryString) {
  const std::string nasty = std::string("a \"quoted\" path\\with\ttab\nnewline\x01\x1f and ") + "\xff\xfe bytes";
  JsonWriter json;
  json.BeginObject().Key(nasty).String(nasty).Key("utf8").String("\xc2\xb5m and \xe2\x82\xac").EndObject();
  const std::string& text = json.text();
  EXPECT_THAT(text, ::testing::HasSubstr(R"("a \"quoted\" path\\with\ttab\nnewline\u0001\u001f and )"));
  EXPECT_THAT(text, ::testing::HasSubstr("\"utf8\": \"\xc2\xb5m and \xe2\x82\xac\""));  // valid UTF-8 kept as is
  const nlohmann::json parsed = nlohmann::json::parse(text);
  const std::string replaced = "a \"quoted\" path\\with\ttab\nnewline\x01\x1f and \xef\xbf\xbd\xef\xbf\xbd bytes";
  ASSERT_TRUE(parsed.contains(replaced)) << text;
  EXPECT_EQ(parsed[replaced].get<std::string>(), replaced);
}

TEST(JsonWriterTest, BreakLinePutsTheNextItemOnANewLine) {
  JsonWriter json;
  json.BeginObject().Key("name").String("robot").BreakLine(1).Key("bodies").BeginArray();
  json.BreakLine(3).BeginObject().Key("name").String("a").EndObject();
  json.BreakLine(3).BeginObject().Key("name").String("b").EndObject();
  json.EndArray().BreakLine(1).Key("frames").BeginArray().String("f").String("g").EndArray().EndObject();
  EXPECT_EQ(json.text(),
            "{\"name\": \"robot\",\n \"bodies\": [\n   {\"name\": \"a\"},\n   {\"name\": \"b\"}],\n \"frames\": [\"f\", "
            "\"g\"]}");
  CAIRN_EXPECT_THROWS_WITH(json.BreakLine(-1), std::invalid_argument, "indent -1");
}

TEST(JsonWriterTest, CallsOutOfOrderAreRefused) {
  CAIRN_EXPECT_THROWS_WITH(JsonWriter().BeginObject().String("x"), std::logic_error, "String in an object",
                           "Key is due");
  CAIRN_EXPECT_THROWS_WITH(JsonWriter().BeginArray().Key("x"), std::logic_error, "Key outside an object");
  CAIRN_EXPECT_THROWS_WITH(JsonWriter().BeginArray().EndObject(), std::logic_error, "EndObject without an open object");
  CAIRN_EXPECT_THROWS_WITH(JsonWriter().BeginObject().Key("a").EndObject(), std::logic_error, "without its value");
  CAIRN_EXPECT_THROWS_WITH(JsonWriter().Integer(1).Integer(2), std::logic_error, "after the top-level value");
  CAIRN_EXPECT_THROWS_WITH(JsonWriter().text(), std::logic_error, "empty document");
  JsonWriter open;
  open.BeginObject().Key("a").BeginArray();
  EXPECT_FALSE(open.complete());
  CAIRN_EXPECT_THROWS_WITH(open.text(), std::logic_error, "2 object(s)/array(s) still open", "{\"a\": [");
}

TEST(JsonWriterTest, WritesFilesAtomicallyWithAFinalNewline) {
  const std::filesystem::path dir = std::filesystem::path(::testing::TempDir()) / "json_writer_test";
  std::filesystem::create_directories(dir);
  JsonWriter json;
  json.BeginObject().Key("a").Integer(1).EndObject();
  json.WriteFile((dir / "out.json").string());
  std::ifstream in(dir / "out.json");
  std::stringstream contents;
  contents << in.rdbuf();
  EXPECT_EQ(contents.str(), "{\"a\": 1}\n");
  CAIRN_EXPECT_THROWS_WITH(json.WriteFile("/nonexistent_cairn_dir/out.json"), std::runtime_error,
                           "/nonexistent_cairn_dir/out.json");
  JsonWriter unfinished;
  unfinished.BeginArray();
  CAIRN_EXPECT_THROWS_WITH(unfinished.WriteFile((dir / "never.json").string()), std::logic_error, "still open");
  EXPECT_FALSE(std::filesystem::exists(dir / "never.json"));
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace cairn
