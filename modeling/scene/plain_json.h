// The fast path of strict JSON reading (strict_json.h): plain JSON — strings in well-formed
// UTF-8 without escapes, no duplicate keys, finite numbers, nesting up to kMaxPlainJsonDepth —
// read straight into the document, with the same value types and numbers as nlohmann's
// parser (unsigned, signed integer or double, by the same rules; doubles correctly rounded
// like strtod). Anything else, every error included, is left to the strict SAX parser, which
// gives the message with its path or its line and column: a scene pays for positions only
// when it has an error, and a large scene of plain objects loads at a few times less cost.
#pragma once
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

namespace qacc {

constexpr int kMaxPlainJsonDepth = 256;

// The document, or nullopt when `text` is not plain JSON as above (valid or not).
std::optional<nlohmann::json> parsePlainJson(const std::string& text);

}  // namespace qacc
