#include "cairn/common/internal/yaml_reader.h"

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "expect_throws.h"

namespace cairn::internal {
namespace {

constexpr const char* kFile = R"(name: demo
size: 3
ratio: 0.5
flag: yes
corner: [1, 2.5]
labels: [a, b]
nested:
  depth: 2
empty:
)";

YamlReader Read(const std::string& text) { return YamlReader::FromText("dir/demo.yaml", text); }

TEST(YamlReaderTest, ReadsTypedValues) {
  const YamlReader yaml = Read(kFile);
  const YAML::Node& root = yaml.root();
  EXPECT_EQ(yaml.String(root, "name", "the file"), "demo");
  EXPECT_EQ(yaml.Integer(root, "size", "the file", 1, 10), 3);
  EXPECT_EQ(yaml.Number(root, "ratio", "the file"), 0.5);
  EXPECT_EQ(yaml.Number(root, "missing", "the file", 7.0), 7.0);
  EXPECT_EQ(yaml.Number(root, "empty", "the file", 7.0), 7.0);  // a key without a value counts as absent
  EXPECT_EQ(yaml.Integer(root, "missing", "the file", 0, 9, 4), 4);
  EXPECT_EQ(yaml.String(root, "missing", "the file", "x"), "x");
  EXPECT_TRUE(yaml.AsBool(root["flag"], "flag"));
  EXPECT_EQ(yaml.Numbers(root["corner"], "corner", 2), Eigen::Vector2d(1.0, 2.5));
  EXPECT_EQ(yaml.NumberList(root["corner"], "corner", 5), (std::vector<double>{1.0, 2.5}));
  EXPECT_EQ(yaml.Strings(root["labels"], "labels"), (std::vector<std::string>{"a", "b"}));
  EXPECT_EQ(yaml.Strings(root["labels"], "labels", 2).size(), 2u);
  EXPECT_TRUE(YamlReader::Has(root, "nested"));
  EXPECT_FALSE(YamlReader::Has(root, "empty"));
  EXPECT_FALSE(YamlReader::Has(root["name"], "x"));  // not a mapping
  EXPECT_EQ(yaml.folder(), "dir/");
  EXPECT_EQ(yaml.Resolve("model.onnx"), "dir/model.onnx");
  EXPECT_EQ(yaml.Resolve("/abs/model.onnx"), "/abs/model.onnx");
  EXPECT_EQ(yaml.text(), kFile);
  EXPECT_EQ(YamlReader::Dump(root["corner"]), "[1, 2.5]");
  yaml.CheckKeys(root, {"name", "size", "ratio", "flag", "corner", "labels", "nested", "empty"}, "the file");
}

TEST(YamlReaderTest, MistakesNameTheFileTheLineAndTheKey) {
  const YamlReader yaml = Read(kFile);
  const YAML::Node& root = yaml.root();
  CAIRN_EXPECT_THROWS_WITH(yaml.Number(root, "name", "the file"), std::invalid_argument,
                           "In 'dir/demo.yaml' line 1: 'name' must be a number, got 'demo'.");
  CAIRN_EXPECT_THROWS_WITH(yaml.Integer(root, "ratio", "the file", 0, 9), std::invalid_argument,
                           "In 'dir/demo.yaml' line 3: 'ratio' must be an integer in [0, 9], got '0.5'.");
  CAIRN_EXPECT_THROWS_WITH(yaml.Integer(root, "size", "the file", 5, 9), std::invalid_argument, "line 2",
                           "in [5, 9], got '3'");
  CAIRN_EXPECT_THROWS_WITH(yaml.Number(root, "missing", "the file"), std::invalid_argument,
                           "In 'dir/demo.yaml' line 1: missing key 'missing' in the file.");
  CAIRN_EXPECT_THROWS_WITH(yaml.Number(root, "empty", "the file"), std::invalid_argument,
                           "key 'empty' in the file has no value");
  CAIRN_EXPECT_THROWS_WITH(yaml.Numbers(root["corner"], "corner", 3), std::invalid_argument, "line 5",
                           "'corner' must be a list of 3 numbers, got '[1, 2.5]'");
  CAIRN_EXPECT_THROWS_WITH(yaml.NumberList(root["corner"], "corner", 1), std::invalid_argument,
                           "'corner' has 2 numbers, more than the 1 allowed");
  CAIRN_EXPECT_THROWS_WITH(yaml.Strings(root["labels"], "labels", 3), std::invalid_argument,
                           "'labels' must be a list of 3 names");
  CAIRN_EXPECT_THROWS_WITH(yaml.AsString(root["corner"], "corner"), std::invalid_argument,
                           "'corner' must be a single value, got '[1, 2.5]'");
  CAIRN_EXPECT_THROWS_WITH(yaml.AsBool(root["name"], "name"), std::invalid_argument, "'name' must be true or false");
  CAIRN_EXPECT_THROWS_WITH(yaml.CheckKeys(root, {"name", "size", "ratio", "flag", "corner", "labels", "nest", "empty"},
                                          "the file"),
                           std::invalid_argument, "line 7: unknown key 'nested' in the file.",
                           "Did you mean 'nest'?", "Allowed keys: 'name', 'size'");
  CAIRN_EXPECT_THROWS_WITH(yaml.CheckKeys(root["corner"], {"x"}, "corner"), std::invalid_argument,
                           "line 5: corner must be a mapping");
  CAIRN_EXPECT_THROWS_WITH(yaml.Fail(root["nested"]["depth"], "too deep"), std::invalid_argument,
                           "In 'dir/demo.yaml' line 8: too deep");
  // A node that is not in the file has no line.
  EXPECT_STREQ(yaml.Error(root["nowhere"], "gone").what(), "In 'dir/demo.yaml': gone");
}

TEST(YamlReaderTest, NonFiniteNumbersAreRefused) {
  const YamlReader yaml = Read("a: .nan\nb: .inf\nc: -.inf\n");
  for (const char* key : {"a", "b", "c"}) {
    CAIRN_EXPECT_THROWS_WITH(yaml.Number(yaml.root(), key, "the file"), std::invalid_argument,
                             std::string("'") + key + "' must be a finite number");
  }
}

// yaml-cpp keeps the first of two equal keys and ignores the second; the reader refuses the file instead.
TEST(YamlReaderTest, DuplicateKeysAreRefusedAtLoad) {
  CAIRN_EXPECT_THROWS_WITH(Read("a: 1\nb: 2\na: 3\n"), std::invalid_argument,
                           "In 'dir/demo.yaml' line 3: the key 'a' appears twice in one mapping (first at line 1)");
  CAIRN_EXPECT_THROWS_WITH(Read("outer:\n  list:\n    - {x: 1, y: 2, x: 3}\n"), std::invalid_argument, "line 3",
                           "the key 'x' appears twice");
  CAIRN_EXPECT_THROWS_WITH(Read("a: 1\n'a': 2\n"), std::invalid_argument, "line 2", "'a' appears twice");
  // The same key in different mappings, equal values, and aliases are fine.
  const YamlReader fine = Read("one: {x: 1}\ntwo: {x: 1}\nbase: &b {k: 1}\nthree: *b\nlist: [x, x]\n");
  EXPECT_EQ(fine.Integer(fine.root()["three"], "k", "three", 0, 9), 1);
}

TEST(YamlReaderTest, UnreadableMalformedOrNonMappingFiles) {
  CAIRN_EXPECT_THROWS_WITH(YamlReader("/nonexistent/file.yaml"), std::invalid_argument,
                           "Cannot read '/nonexistent/file.yaml'; check that the file exists and is readable.");
  CAIRN_EXPECT_THROWS_WITH(Read("name: [unclosed\n"), std::invalid_argument, "Malformed YAML in 'dir/demo.yaml' at line");
  CAIRN_EXPECT_THROWS_WITH(Read("- a\n- b\n"), std::invalid_argument, "'dir/demo.yaml' must hold a YAML mapping");
  CAIRN_EXPECT_THROWS_WITH(Read(""), std::invalid_argument, "must hold a YAML mapping");
  // From a real file.
  const std::string path = ::testing::TempDir() + "/yaml_reader_test.yaml";
  std::ofstream(path) << "a: 1\n";
  EXPECT_EQ(YamlReader(path).Integer(YamlReader(path).root(), "a", "the file", 0, 9), 1);
  // A caller's size limit is checked from the file's size, before it is read; the default is kMaxFileBytes.
  EXPECT_EQ(YamlReader(path, 5).Integer(YamlReader(path, 5).root(), "a", "the file", 0, 9), 1);
  CAIRN_EXPECT_THROWS_WITH(YamlReader(path, 4), std::invalid_argument,
                           "Cannot read '" + path + "': it has 5 bytes, more than the 4 a file of its kind may have.");
  CAIRN_EXPECT_THROWS_WITH(YamlReader(path, 0), std::invalid_argument, "size limit 0", "must be in [1, 268435456]");
  CAIRN_EXPECT_THROWS_WITH(YamlReader(path, YamlReader::kMaxFileBytes + 1), std::invalid_argument,
                           "size limit 268435457");
  std::filesystem::remove(path);
  // A long value is quoted short in messages.
  const std::string long_list = "v: [" + std::string(200, '1') + "]\n";
  const YamlReader yaml = Read(long_list);
  EXPECT_EQ(YamlReader::Dump(yaml.root()["v"]).size(), 80u);
}

}  // namespace
}  // namespace cairn::internal
