// JSON values read back what they wrote, keep key order, and name line and column on bad input.
#include "core/json.h"

#include <gtest/gtest.h>
#include <limits>

using engine::Json;
using engine::parseJson;

TEST(Json, WritesAndReadsBackEveryType) {
    Json doc = Json::object();
    doc["name"] = "frame \"12\"\n";
    doc["count"] = 151;
    doc["ratio"] = 0.1 + 0.2;  // not a short decimal: must still read back exactly
    doc["big"] = std::uint64_t(1) << 52;
    doc["ok"] = true;
    doc["none"] = Json();
    doc["list"].push(1);
    doc["list"].push("two");
    doc["nested"]["inner"]["deep"] = -3.5e-7;
    const std::string text = doc.dump();
    auto back = parseJson(text, "doc.json");
    ASSERT_TRUE(back.ok()) << back.error().message;
    EXPECT_EQ(*back, doc);
    EXPECT_EQ(back->dump(), text);
    EXPECT_EQ(back->get("ratio").number(), 0.1 + 0.2);
    EXPECT_EQ(back->get("name").string(), "frame \"12\"\n");
    EXPECT_EQ(back->get("list").items().size(), 2u);
}

TEST(Json, KeepsKeysInInsertionOrderAndReplacesInPlace) {
    Json doc;
    doc["b"] = 1;
    doc["a"] = 2;
    doc["b"] = 3;
    ASSERT_EQ(doc.members().size(), 2u);
    EXPECT_EQ(doc.members()[0].first, "b");
    EXPECT_EQ(doc.members()[0].second.number(), 3.0);
    EXPECT_TRUE(doc.erase("b"));
    EXPECT_FALSE(doc.erase("b"));
    EXPECT_EQ(doc.members().front().first, "a");
}

TEST(Json, IntegersAreWrittenWithoutAFractionAndNonFiniteAsNull) {
    EXPECT_EQ(Json(12).dump(), "12\n");
    EXPECT_EQ(Json(-0.25).dump(), "-0.25\n");
    EXPECT_EQ(Json(std::numeric_limits<double>::infinity()).dump(), "null\n");
}

TEST(Json, WritesDeepContainersOnOneLine) {
    Json doc;
    doc["frames"]["0"]["png"] = "fnv1a64:00";
    doc["frames"]["0"]["csv"]["frame"] = "0";
    EXPECT_EQ(doc.dump(2),
              "{\n  \"frames\": {\n    \"0\": {\"png\": \"fnv1a64:00\", \"csv\": {\"frame\": "
              "\"0\"}}\n  }\n}\n");
}

TEST(Json, ReadsEscapesAndUnicode) {
    auto v = parseJson(R"(["a\u00e9\ud83d\ude00\/\t", 1E2, -0, [], {}])", "x");
    ASSERT_TRUE(v.ok()) << v.error().message;
    EXPECT_EQ(v->items()[0].string(), "a\xc3\xa9\xf0\x9f\x98\x80/\t");
    EXPECT_EQ(v->items()[1].number(), 100.0);
    EXPECT_TRUE(v->items()[3].isArray());
    EXPECT_TRUE(v->items()[4].isObject());
}

TEST(Json, ErrorsNameTheSourceLineAndColumn) {
    auto expectError = [](const char* text, const char* message) {
        auto v = parseJson(text, "job.json");
        ASSERT_FALSE(v.ok()) << text;
        EXPECT_EQ(v.error().message, message) << text;
    };
    expectError("{\n  \"a\": 1\n  \"b\": 2\n}", "job.json:3:3: expected ',' or '}'");
    expectError("[1, 2", "job.json:1:6: expected ',' or ']'");
    expectError("{\"a\": tru}", "job.json:1:7: unexpected character 't'");
    expectError("\"abc", "job.json:1:5: unterminated string");
    expectError("{} x", "job.json:1:4: unexpected text after the document");
    expectError("", "job.json:1:1: unexpected end of the document");
    expectError("[01.]", "job.json:1:5: expected a digit after '.'");
    expectError(std::string(1000, '[').c_str(), "job.json:1:258: nested too deeply");
}
