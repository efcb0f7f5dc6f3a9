#include "engine/io/json_reader.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "tests/engine/error_test_support.h"

namespace baize::engine {
namespace {

const nlohmann::json kDocument = nlohmann::json::parse(R"({
  "count": 3, "ratio": 0.5, "flag": true, "label": "x", "empty": "",
  "inner": {"deep": {"size_m": -1}},
  "list": [{"a": 1}, 7]
})");

TEST(JsonReader, ReadsValuesOfTheRightTypeAndRange) {
  const JsonReader root(kDocument, "doc");
  EXPECT_EQ(root.integer("count", 0, 10), 3);
  EXPECT_EQ(root.positiveNumber("ratio"), 0.5);
  EXPECT_EQ(root.finiteNumber("count"), 3.0);  // an integer is a number
  EXPECT_TRUE(root.boolean("flag"));
  EXPECT_EQ(root.text("label"), "x");
  EXPECT_EQ(root.object("inner").object("deep").finiteNumber("size_m"), -1.0);
}

TEST(JsonReader, ErrorsNameTheSourceThePathAndTheValue) {
  const JsonReader root(kDocument, "doc");
  EXPECT_MENTIONS(invalidArgumentMessage([&] { root.integer("count", 4, 10); }),
                  "doc: count = 3 is not allowed: it must be an integer in [4, 10]");
  EXPECT_MENTIONS(invalidArgumentMessage([&] { root.integer("ratio", 0, 10); }), "ratio = 0.5");
  EXPECT_MENTIONS(invalidArgumentMessage([&] { root.text("empty"); }), "empty = \"\"");
  EXPECT_MENTIONS(invalidArgumentMessage([&] { root.boolean("count"); }), "count = 3");
  EXPECT_MENTIONS(invalidArgumentMessage([&] { root.object("label"); }), "label = \"x\"");
  EXPECT_MENTIONS(invalidArgumentMessage(
                      [&] { root.object("inner").object("deep").nonNegativeNumber("size_m"); }),
                  "doc: inner.deep.size_m = -1 is not allowed: it must be a finite number >= 0");
  EXPECT_MENTIONS(invalidArgumentMessage([&] { root.objectArray("list"); }), "list[1] = 7");
  EXPECT_MENTIONS(invalidArgumentMessage([&] { root.objectArray("ratio"); }), "non-empty array");
  EXPECT_MENTIONS(invalidArgumentMessage([&] { root.finiteNumber("absent"); }),
                  "doc: absent is missing");
}

TEST(JsonReader, ExactKeysNameTheUnknownAndTheMissing) {
  const JsonReader inner(kDocument["inner"], "doc", "inner");
  EXPECT_NO_THROW(inner.requireExactKeys({"deep"}));
  EXPECT_MENTIONS(invalidArgumentMessage([&] { inner.requireExactKeys({"shallow"}); }),
                  "doc: inner.deep = {\"size_m\":-1} is not allowed: unknown key; the keys here "
                  "are shallow");
  EXPECT_MENTIONS(invalidArgumentMessage([&] {
                    inner.requireExactKeys({"deep", "wide"});
                  }),
                  "doc: inner.wide is missing");
}

TEST(JsonReader, TheDocumentMustBeAnObject) {
  const nlohmann::json array = nlohmann::json::array({1, 2});
  EXPECT_MENTIONS(invalidArgumentMessage([&] { JsonReader(array, "doc"); }),
                  "doc: the document = [1,2] is not allowed");
}

// A key given twice in one object is refused with the source and the key's path, at any depth and
// inside arrays; the same key in different objects is not a duplicate.
TEST(JsonReader, ParsingRefusesAKeyGivenTwiceInOneObject) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {R"({"cue": [-0.6, 0], "cue": [0, 0]})", "doc: cue appears twice, which is not allowed"},
      {R"({"balls": {"cue": [-0.6, 0], "cue": [0, 0]}})", "doc: balls.cue appears twice"},
      {R"({"a": {"b": {"c": 1, "d": 2, "c": 3}}})", "doc: a.b.c appears twice"},
      {R"({"cases": [{"x": 1}, [0, {"y": 1}], {"z": {}, "z": 2}]})",
       "doc: cases[2].z appears twice"},
      {R"({"cases": [[0, {"y": 1, "y": 1}]]})", "doc: cases[0][1].y appears twice"},
      {R"([{"k": 1}, {"k": 1, "k": 1}])", "doc: [1].k appears twice"},
  };
  for (const auto& [document, expected] : cases) {
    const std::string& text = document;  // a lambda may not capture a structured binding (C++17)
    EXPECT_MENTIONS(invalidArgumentMessage([&] { JsonReader::parseText(text, "doc"); }), expected);
  }
  const std::string distinct = R"({"a": {"k": 1}, "b": {"k": 2}, "k": [{"k": 3}, {"k": 4}]})";
  EXPECT_EQ(JsonReader::parseText(distinct, "doc"), nlohmann::json::parse(distinct));
}

TEST(JsonReader, ParsingNamesTheSourceOfTextThatIsNotJson) {
  EXPECT_MENTIONS(invalidArgumentMessage([] { JsonReader::parseText("{\"a\": }", "doc"); }),
                  "doc: not valid JSON (");
  EXPECT_MENTIONS(invalidArgumentMessage([] { JsonReader::parseText("[1", "line 3", "one line"); }),
                  ") is not allowed: one line");
}

// Files go through the same check: the message names the file.
TEST(JsonReader, ParsingAFileRefusesAKeyGivenTwice) {
  const std::string path = (std::filesystem::temp_directory_path() /
                            ("baize_json_reader_test_" + std::to_string(::getpid()) + ".json"))
                               .string();
  std::ofstream(path) << R"({"corner_pocket": {"mouth_m": 0.11, "mouth_m": 0.12}})";
  EXPECT_MENTIONS(invalidArgumentMessage([&] { JsonReader::parseFile(path); }),
                  path + ": corner_pocket.mouth_m appears twice, which is not allowed");
  std::filesystem::remove(path);
}

// Nesting beyond 64 levels is refused as it is parsed (writing such a value back into a message
// recursed once per level: 70000 levels overflowed the stack); 64 levels are read.
TEST(JsonReader, ParsingRefusesNestingDeeperThan64Levels) {
  const auto nested = [](int levels) {
    return std::string(levels, '[') + std::string(levels, ']');
  };
  EXPECT_NO_THROW(JsonReader::parseText(nested(64), "doc"));
  EXPECT_MENTIONS(invalidArgumentMessage([&] { JsonReader::parseText(nested(65), "doc"); }),
                  "doc: objects and arrays nested more than 64 levels deep are not allowed");
  EXPECT_MENTIONS(invalidArgumentMessage([&] { JsonReader::parseText(nested(70000), "doc"); }),
                  "more than 64 levels");
}

// The parser takes a NUL byte for the end of the text: what follows would be ignored.
TEST(JsonReader, ParsingRefusesANulByte) {
  const std::string text = std::string("{\"a\": 1}") + '\0' + "{{{";
  EXPECT_MENTIONS(invalidArgumentMessage([&] { JsonReader::parseText(text, "doc"); }),
                  "doc: a NUL byte at offset 8 is not allowed");
}

TEST(JsonReader, ParsingAFileRefusesADirectoryNamingIt) {
  const std::string folder = std::filesystem::temp_directory_path().string();
  EXPECT_MENTIONS(invalidArgumentMessage([&] { JsonReader::parseFile(folder); }),
                  folder + ": a directory is not allowed: it must be a file");
}

// A value quoted in a message is cut after 200 characters, saying how long it was, and bytes that
// are not UTF-8 are replaced instead of failing the message.
TEST(JsonReader, MessagesQuoteValuesShortAndSafe) {
  nlohmann::json document;
  document["long"] = std::string(5000, 'x');
  document["bytes"] = std::string("a\xff");
  const JsonReader reader(document, "doc");
  const std::string long_message =
      invalidArgumentMessage([&] { reader.reject("long", "it must be short"); });
  EXPECT_MENTIONS(long_message, "... (5002 characters) is not allowed: it must be short");
  EXPECT_LT(long_message.size(), 300u);
  EXPECT_MENTIONS(invalidArgumentMessage([&] { reader.reject("bytes", "it must be text"); }),
                  "doc: bytes = \"a\xef\xbf\xbd\" is not allowed");
}

// Keys in a message's path show control characters escaped (a NUL ended the message there) and a
// long key cut.
TEST(JsonReader, MessagesShowKeysEscapedAndShort) {
  nlohmann::json document;
  document[std::string("a\0b", 3)] = 1;
  document[std::string(300, 'k')] = 2;
  const JsonReader reader(document, "doc");
  const std::string nul =
      invalidArgumentMessage([&] { reader.reject(std::string("a\0b", 3), "no"); });
  EXPECT_MENTIONS(nul, "doc: a\\u0000b = 1 is not allowed: no");
  const std::string long_key =
      invalidArgumentMessage([&] { reader.reject(std::string(300, 'k'), "no"); });
  EXPECT_MENTIONS(long_key, "... (300 characters) = 2 is not allowed: no");
}

}  // namespace
}  // namespace baize::engine
