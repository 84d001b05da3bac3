// Where a value is in a JSON text, for error messages. The loader reads a document without
// positions (plain_json.h keeps none, to stay cheap per value), so an error found while the
// scene is built, which names a JSON Pointer (/objects/3/radius), is located afterwards by
// scanning the text once more: the cost falls on the error only.
#pragma once
#include <cstddef>
#include <string>

namespace qacc {

struct TextPosition {
  std::size_t line = 1;    // from 1
  std::size_t column = 1;  // from 1, in bytes
};

// The line and column of byte `offset` of `text` (an offset past the end gives the end).
TextPosition textPosition(const std::string& text, std::size_t offset);

// The byte offset where the value at `pointer` starts in `text`; when the pointer names
// something the text does not hold, the offset of its deepest ancestor that it does. "" and
// "/" are the root. Where an object repeats a key, its last occurrence is taken (the one a
// duplicate-key error names). Any text is accepted, well-formed or not; the scan is linear
// in the text and never recurses.
std::size_t jsonPointerOffset(const std::string& text, const std::string& pointer);

// "PROBLEM (line L, column C)": the problem of an error at `pointer` with its position.
std::string withTextPosition(const std::string& problem, const std::string& text, const std::string& pointer);

}  // namespace qacc
