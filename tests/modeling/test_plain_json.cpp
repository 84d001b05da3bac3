// The fast path of strict JSON reading (modeling/scene/plain_json.h): on plain JSON it gives
// the document nlohmann's parser gives, value types included; on anything else it declines,
// so that the strict parser reports errors with their path or line and column.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "modeling/scene/plain_json.h"
#include "modeling/scene/scene_error.h"
#include "modeling/scene/strict_json.h"

namespace fs = std::filesystem;
using nlohmann::json;
using namespace qacc;

namespace {

// Same structure, same value types (unsigned, signed, double), same values and bits.
void expectIdentical(const json& a, const json& b, const std::string& path) {
  ASSERT_EQ(a.type(), b.type()) << path;
  switch (a.type()) {
    case json::value_t::object: {
      ASSERT_EQ(a.size(), b.size()) << path;
      for (auto it = a.begin(); it != a.end(); ++it) {
        ASSERT_TRUE(b.contains(it.key())) << path << "/" << it.key();
        expectIdentical(it.value(), b.at(it.key()), path + "/" + it.key());
      }
      break;
    }
    case json::value_t::array:
      ASSERT_EQ(a.size(), b.size()) << path;
      for (std::size_t i = 0; i < a.size(); ++i) expectIdentical(a[i], b[i], path + "/" + std::to_string(i));
      break;
    case json::value_t::number_float: {
      const double x = a.get<double>(), y = b.get<double>();
      EXPECT_EQ(std::memcmp(&x, &y, sizeof x), 0) << path << ": " << x << " vs " << y;
      break;
    }
    default: EXPECT_EQ(a, b) << path;
  }
}

void expectSameAsNlohmann(const std::string& text) {
  SCOPED_TRACE(text.substr(0, 200));
  const auto plain = parsePlainJson(text);
  ASSERT_TRUE(plain.has_value());
  expectIdentical(*plain, json::parse(text), "");
}

}  // namespace

TEST(PlainJson, SameDocumentAsNlohmannOnEveryShippedScene) {
  int scenes = 0;
  for (const auto& e : fs::recursive_directory_iterator(fs::path(QACC_SOURCE_DIR) / "scenes")) {
    if (e.path().extension() != ".json") continue;
    std::ifstream in(e.path());
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    expectSameAsNlohmann(text);
    ++scenes;
  }
  EXPECT_GE(scenes, 17);
}

TEST(PlainJson, NumbersTypedAndRoundedAsNlohmann) {
  expectSameAsNlohmann(R"([0, -0, 7, -7, 18446744073709551615, 18446744073709551616, -9223372036854775808,
      -9223372036854775809, 99999999999999999999999, 0.1, -0.0, 1E2, 1e+2, 2.5e-3, 1.7976931348623157e308,
      4.9406564584124654e-324, 0.30000000000000004, 123456789012345678901234567890e-10, 1.00000000000000011102230246251565])");
  expectSameAsNlohmann(R"( {"a": {"b": [[], {}, [true, false, null]], "": "x y z)" "\xc3\xa9 \xe2\x80\x94 \xf0\x9f\x98\x80"
                       R"("}, "c": "~/"} )");
  expectSameAsNlohmann("3");
}

TEST(PlainJson, DeclinesWhatIsNotPlain) {
  for (const std::string& text : std::vector<std::string>{R"(["a\nb"])", "[\"\xc3\"]", "[\"\xc0\xaf\"]", "[\"\xed\xa0\x80\"]", "[\"\xf4\x90\x80\x80\"]", "[\"\xff\"]", R"({"a": 1, "a": 2})", "[1e999]", "[-1e999]", "[1e-400]", "[01]", "[1.]",
        "[1e]", "[-]", "[1,]", R"({"a": 1,})", "[1] x", "", "   ", "\xef\xbb\xbf[1]", "[tru]", "[\"a\tb\"]",
        std::string(300, '[') + std::string(300, ']'), "[1 2]", R"({"a" 1})", "{1: 2}", "[\"unterminated]"}) {
    SCOPED_TRACE(text);
    EXPECT_FALSE(parsePlainJson(text).has_value());
  }
}

// What the fast path declines still loads, or is refused with the strict parser's message.
TEST(PlainJson, StrictParserTakesOverWhatIsDeclined) {
  EXPECT_EQ(parseStrictJson(R"({"a": "x\ny", "b": [1e-400]})", "f.json")["a"], "x\ny");
  EXPECT_EQ(parseStrictJson(std::string(300, '[') + std::string(300, ']'), "f.json").size(), 1u);
  try {
    parseStrictJson(R"({"o": [{"a": 1, "a": 2}]})", "f.json");
    FAIL() << "accepted";
  } catch (const SceneError& e) {
    EXPECT_EQ(std::string(e.what()), "f.json: /o/0/a: duplicate key 'a'");
  }
  try {
    parseStrictJson("{\n\"a\": [1,\n]}", "f.json");
    FAIL() << "accepted";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("f.json: /: JSON syntax error at line 3, column"), std::string::npos) << e.what();
  }
}
