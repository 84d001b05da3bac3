#include "modeling/scene/plain_json.h"

#include <charconv>
#include <cstdint>
#include <limits>

namespace qacc {

namespace {

using nlohmann::json;

class PlainReader {
 public:
  explicit PlainReader(const std::string& text) : p_(text.data()), end_(text.data() + text.size()) {}

  // False when the text is not plain JSON; `out` is then unspecified.
  bool document(json& out) {
    skipSpace();
    if (!value(out, 0)) return false;
    skipSpace();
    return p_ == end_;
  }

 private:
  const char* p_;
  const char* end_;

  void skipSpace() {
    while (p_ != end_ && (*p_ == ' ' || *p_ == '\n' || *p_ == '\r' || *p_ == '\t')) ++p_;
  }

  bool literal(const char* word, std::size_t n) {
    if (std::size_t(end_ - p_) < n) return false;
    for (std::size_t i = 0; i < n; ++i)
      if (p_[i] != word[i]) return false;
    p_ += n;
    return true;
  }

  bool value(json& out, int depth) {
    if (p_ == end_) return false;
    switch (*p_) {
      case '{': return object(out, depth + 1);
      case '[': return array(out, depth + 1);
      case '"': {
        std::string s;
        if (!string(s)) return false;
        out = json(std::move(s));
        return true;
      }
      case 't':
        if (!literal("true", 4)) return false;
        out = json(true);
        return true;
      case 'f':
        if (!literal("false", 5)) return false;
        out = json(false);
        return true;
      case 'n':
        if (!literal("null", 4)) return false;
        out = json(nullptr);
        return true;
      default: return number(out);
    }
  }

  // The continuation bytes of a UTF-8 sequence: the first in [lo, hi], the others in
  // [0x80, 0xbf] (the well-formed sequences of Unicode's table 3-7, as nlohmann checks them).
  bool continuation(int count, unsigned char lo, unsigned char hi) {
    for (int i = 0; i < count; ++i, ++p_) {
      if (p_ == end_) return false;
      const unsigned char c = static_cast<unsigned char>(*p_);
      if (c < (i == 0 ? lo : 0x80) || c > (i == 0 ? hi : 0xbf)) return false;
    }
    return true;
  }

  // A string without escapes or control characters, in well-formed UTF-8.
  bool string(std::string& out) {
    const char* begin = ++p_;  // past '"'
    while (p_ != end_) {
      const unsigned char c = static_cast<unsigned char>(*p_);
      if (c == '"') {
        out.assign(begin, p_);
        ++p_;
        return true;
      }
      if (c == '\\' || c < 0x20) return false;
      ++p_;
      if (c < 0x80) continue;
      bool ok;
      if (c >= 0xc2 && c <= 0xdf) ok = continuation(1, 0x80, 0xbf);
      else if (c == 0xe0) ok = continuation(2, 0xa0, 0xbf);
      else if ((c >= 0xe1 && c <= 0xec) || c == 0xee || c == 0xef) ok = continuation(2, 0x80, 0xbf);
      else if (c == 0xed) ok = continuation(2, 0x80, 0x9f);
      else if (c == 0xf0) ok = continuation(3, 0x90, 0xbf);
      else if (c >= 0xf1 && c <= 0xf3) ok = continuation(3, 0x80, 0xbf);
      else if (c == 0xf4) ok = continuation(3, 0x80, 0x8f);
      else ok = false;
      if (!ok) return false;
    }
    return false;
  }

  static bool digit(char c) { return c >= '0' && c <= '9'; }

  // RFC 8259 numbers, typed as nlohmann types them: without fraction or exponent, an
  // unsigned integer (no sign) or a signed one (minus) when it fits, a double otherwise.
  bool number(json& out) {
    const char* begin = p_;
    const bool negative = *p_ == '-';
    if (negative) ++p_;
    if (p_ == end_ || !digit(*p_)) return false;
    if (*p_ == '0') {
      ++p_;
    } else {
      while (p_ != end_ && digit(*p_)) ++p_;
    }
    bool integer = true;
    if (p_ != end_ && *p_ == '.') {
      integer = false;
      ++p_;
      if (p_ == end_ || !digit(*p_)) return false;
      while (p_ != end_ && digit(*p_)) ++p_;
    }
    if (p_ != end_ && (*p_ == 'e' || *p_ == 'E')) {
      integer = false;
      ++p_;
      if (p_ != end_ && (*p_ == '+' || *p_ == '-')) ++p_;
      if (p_ == end_ || !digit(*p_)) return false;
      while (p_ != end_ && digit(*p_)) ++p_;
    }
    if (integer) {
      std::uint64_t magnitude = 0;
      bool fits = true;
      for (const char* d = begin + (negative ? 1 : 0); d != p_; ++d) {
        const std::uint64_t v = std::uint64_t(*d - '0');
        if (magnitude > (std::numeric_limits<std::uint64_t>::max() - v) / 10) {
          fits = false;
          break;
        }
        magnitude = magnitude * 10 + v;
      }
      if (fits && !negative) {
        out = json(json::number_unsigned_t(magnitude));
        return true;
      }
      if (fits && magnitude <= std::uint64_t(std::numeric_limits<std::int64_t>::max()) + 1) {
        out = json(json::number_integer_t(magnitude == 0 ? 0 : -std::int64_t(magnitude - 1) - 1));
        return true;
      }
    }
    double v = 0;
    const auto r = std::from_chars(begin, p_, v);
    // Out of range (overflow, and underflow, which strtod would round) and anything not
    // read to the end: the strict parser decides.
    if (r.ec != std::errc() || r.ptr != p_) return false;
    out = json(v);
    return true;
  }

  bool object(json& out, int depth) {
    if (depth > kMaxPlainJsonDepth) return false;
    ++p_;  // '{'
    out = json::object();
    auto& members = out.get_ref<json::object_t&>();
    skipSpace();
    if (p_ != end_ && *p_ == '}') {
      ++p_;
      return true;
    }
    std::string key;
    for (;;) {
      if (p_ == end_ || *p_ != '"' || !string(key)) return false;
      skipSpace();
      if (p_ == end_ || *p_ != ':') return false;
      ++p_;
      skipSpace();
      const auto [it, inserted] = members.try_emplace(std::move(key));
      if (!inserted) return false;  // duplicate key: refused by the strict parser, with its path
      if (!value(it->second, depth)) return false;
      skipSpace();
      if (p_ == end_) return false;
      if (*p_ == '}') {
        ++p_;
        return true;
      }
      if (*p_ != ',') return false;
      ++p_;
      skipSpace();
      key.clear();
    }
  }

  bool array(json& out, int depth) {
    if (depth > kMaxPlainJsonDepth) return false;
    ++p_;  // '['
    out = json::array();
    auto& elements = out.get_ref<json::array_t&>();
    skipSpace();
    if (p_ != end_ && *p_ == ']') {
      ++p_;
      return true;
    }
    for (;;) {
      elements.emplace_back();
      if (!value(elements.back(), depth)) return false;
      skipSpace();
      if (p_ == end_) return false;
      if (*p_ == ']') {
        ++p_;
        return true;
      }
      if (*p_ != ',') return false;
      ++p_;
      skipSpace();
    }
  }
};

}  // namespace

std::optional<json> parsePlainJson(const std::string& text) {
  json doc;
  PlainReader reader(text);
  if (!reader.document(doc)) return std::nullopt;
  return doc;
}

}  // namespace qacc
