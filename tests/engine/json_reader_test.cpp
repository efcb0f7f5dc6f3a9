#include "engine/json_reader.h"

#include <gtest/gtest.h>

#include <string>

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

}  // namespace
}  // namespace baize::engine
