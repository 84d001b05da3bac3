// JSON Pointer → line and column of a scene's text, for the loader's errors.
#include <gtest/gtest.h>

#include <random>
#include <string>

#include "modeling/loader/scene_loader.h"
#include "modeling/scene/json_location.h"
#include "modeling/scene/scene_error.h"

namespace qacc {
namespace {

// The line and column of the first occurrence of `marker` in `text` (where a value starts).
TextPosition positionOf(const std::string& text, const std::string& marker) {
  const std::size_t at = text.find(marker);
  EXPECT_NE(at, std::string::npos) << marker;
  return textPosition(text, at);
}

void expectAt(const std::string& text, const std::string& pointer, const std::string& marker) {
  const TextPosition got = textPosition(text, jsonPointerOffset(text, pointer));
  const TextPosition want = positionOf(text, marker);
  EXPECT_EQ(got.line, want.line) << pointer;
  EXPECT_EQ(got.column, want.column) << pointer;
}

TEST(JsonLocation, LinesAndColumnsCountFromOne) {
  const std::string t = "ab\ncd\n\nef";
  EXPECT_EQ(textPosition(t, 0).line, 1u);
  EXPECT_EQ(textPosition(t, 0).column, 1u);
  EXPECT_EQ(textPosition(t, 1).column, 2u);
  EXPECT_EQ(textPosition(t, 3).line, 2u);
  EXPECT_EQ(textPosition(t, 3).column, 1u);
  EXPECT_EQ(textPosition(t, 7).line, 4u);
  EXPECT_EQ(textPosition(t, 1000).line, 4u);  // past the end: the end
  EXPECT_EQ(textPosition(t, 1000).column, 3u);
}

TEST(JsonLocation, PointersFindTheirValues) {
  const std::string t =
      "{\n"
      "  \"a\": {\"b\": [10, [20, 21], {\"c\": \"x,]}\\\"\"}, 13]},\n"
      "  \"s/l\": 1, \"t~l\": 2,\n"
      "  \"\\u00e9t\\u00e9\": \"summer\", \"\\ud83d\\ude00\": [7],\n"
      "  \"last\": {\"k\": true}\n"
      "}";
  expectAt(t, "", "{");
  expectAt(t, "/", "{");
  expectAt(t, "/a", "{\"b\"");
  expectAt(t, "/a/b", "[10");
  expectAt(t, "/a/b/0", "10");
  expectAt(t, "/a/b/1/1", "21");
  expectAt(t, "/a/b/2/c", "\"x,]}");
  expectAt(t, "/a/b/3", "13");  // after a string holding , ] } and an escaped quote
  expectAt(t, "/s~1l", "1,");
  expectAt(t, "/t~0l", "2,");
  expectAt(t, "/\xc3\xa9t\xc3\xa9", "\"summer");    // a key written with \u escapes
  expectAt(t, "/\xf0\x9f\x98\x80/0", "7]");        // a surrogate pair
  expectAt(t, "/last/k", "true");
}

TEST(JsonLocation, AMissingValueGivesItsDeepestAncestor) {
  const std::string t = "{\"objects\": [\n  {\"type\": \"sphere\"},\n  {\"type\": \"cone\"}\n]}";
  expectAt(t, "/objects/1/radius", "{\"type\": \"cone\"");
  expectAt(t, "/objects/7", "[\n");
  expectAt(t, "/objects/x", "[\n");
  expectAt(t, "/objects/1/type/0", "\"cone\"");  // below a scalar
  expectAt(t, "/camera", "{");
}

TEST(JsonLocation, ARepeatedKeyGivesItsLastOccurrence) {
  const std::string t = "{\"r\": 1,\n \"r\": 2}";
  expectAt(t, "/r", "2}");
}

// Any text, well-formed or not, is scanned to its end without a fault or an endless loop.
TEST(JsonLocation, MalformedTextIsScannedSafely) {
  const std::string base = R"({"a": [1, {"b": "c\"d", "e": [[[]]]}, "\u12"], "f": {"g": tru, "h": })";
  std::mt19937 rng(5);
  for (int trial = 0; trial < 2000; ++trial) {
    std::string t = base.substr(0, rng() % (base.size() + 1));
    if (trial % 2 && !t.empty()) t[rng() % t.size()] = "{}[]\",:\\"[rng() % 8];
    for (const char* p : {"/a/1/e/0/0", "/f/h", "/a/2", "/f/g/x", "/q"}) {
      const std::size_t at = jsonPointerOffset(t, p);
      EXPECT_LE(at, t.size()) << t;
    }
  }
}

TEST(JsonLocation, LoaderErrorsGiveTheLineAndColumnOfTheirValue) {
  const std::string t =
      "{\"format\": \"qacc-scene/1\",\n"
      " \"camera\": {\"eye\": [0, -5, 0], \"target\": [0, 0, 0], \"up\": [0, 0, 1]},\n"
      " \"objects\": [\n"
      "   {\"type\": \"sphere\", \"radius\": 1},\n"
      "   {\"type\": \"sphere\",\n"
      "    \"radius\": -2}\n"
      " ]}\n";
  try {
    parseScene(t, "s.json", ".");
    FAIL() << "accepted a negative radius";
  } catch (const SceneError& e) {
    EXPECT_EQ(e.jsonPath(), "/objects/1/radius");
    EXPECT_EQ(std::string(e.what()), "s.json: /objects/1/radius: expected a positive number, got -2 (line 6, column 15)");
  }
}

}  // namespace
}  // namespace qacc
