#include "modeling/scene/json_location.h"

#include <algorithm>
#include <vector>

namespace qacc {

namespace {

// The reference tokens of a JSON Pointer, unescaped (~1 → /, ~0 → ~).
std::vector<std::string> pointerTokens(const std::string& pointer) {
  std::vector<std::string> tokens;
  if (pointer.empty() || pointer == "/") return tokens;
  std::size_t start = pointer[0] == '/' ? 1 : 0;
  while (true) {
    const std::size_t slash = pointer.find('/', start);
    const std::string raw = pointer.substr(start, slash == std::string::npos ? std::string::npos : slash - start);
    std::string token;
    for (std::size_t i = 0; i < raw.size(); ++i) {
      if (raw[i] == '~' && i + 1 < raw.size() && (raw[i + 1] == '0' || raw[i + 1] == '1')) {
        token += raw[i + 1] == '0' ? '~' : '/';
        ++i;
      } else {
        token += raw[i];
      }
    }
    tokens.push_back(std::move(token));
    if (slash == std::string::npos) break;
    start = slash + 1;
  }
  return tokens;
}

void appendUtf8(std::string& out, unsigned long cp) {
  if (cp < 0x80) {
    out += char(cp);
  } else if (cp < 0x800) {
    out += char(0xC0 | (cp >> 6));
    out += char(0x80 | (cp & 0x3F));
  } else if (cp < 0x10000) {
    out += char(0xE0 | (cp >> 12));
    out += char(0x80 | ((cp >> 6) & 0x3F));
    out += char(0x80 | (cp & 0x3F));
  } else {
    out += char(0xF0 | (cp >> 18));
    out += char(0x80 | ((cp >> 12) & 0x3F));
    out += char(0x80 | ((cp >> 6) & 0x3F));
    out += char(0x80 | (cp & 0x3F));
  }
}

// A forward scan over possibly malformed JSON: every step checks the end of the text.
class Scan {
 public:
  explicit Scan(const std::string& s) : s_(s) {}
  std::size_t at = 0;

  bool end() const { return at >= s_.size(); }
  char peek() const { return end() ? '\0' : s_[at]; }
  void space() {
    while (!end() && (s_[at] == ' ' || s_[at] == '\t' || s_[at] == '\n' || s_[at] == '\r')) ++at;
  }

  // At a '"': the decoded string, leaving `at` after the closing quote.
  std::string string() {
    std::string out;
    ++at;
    while (!end() && s_[at] != '"') {
      if (s_[at] != '\\') {
        out += s_[at++];
        continue;
      }
      ++at;
      if (end()) break;
      const char e = s_[at++];
      switch (e) {
        case 'b': out += '\b'; break;
        case 'f': out += '\f'; break;
        case 'n': out += '\n'; break;
        case 'r': out += '\r'; break;
        case 't': out += '\t'; break;
        case 'u': {
          unsigned long cp = hex4();
          if (cp >= 0xD800 && cp < 0xDC00 && at + 1 < s_.size() && s_[at] == '\\' && s_[at + 1] == 'u') {
            at += 2;
            const unsigned long low = hex4();
            if (low >= 0xDC00 && low < 0xE000) cp = 0x10000 + ((cp - 0xD800) << 10) + (low - 0xDC00);
          }
          appendUtf8(out, cp);
          break;
        }
        default: out += e;  // \" \\ \/ (and anything malformed, as it stands)
      }
    }
    if (!end()) ++at;
    return out;
  }

  // Past one value (string, number, literal, object or array), without recursion.
  void skipValue() {
    space();
    const char c = peek();
    if (c == '"') {
      string();
      return;
    }
    if (c != '{' && c != '[') {
      while (!end() && std::string(",]} \t\n\r").find(s_[at]) == std::string::npos) ++at;
      return;
    }
    std::size_t depth = 0;
    while (!end()) {
      const char d = s_[at];
      if (d == '"') {
        string();
        continue;
      }
      ++at;
      if (d == '{' || d == '[') ++depth;
      if ((d == '}' || d == ']') && --depth == 0) return;
    }
  }

 private:
  const std::string& s_;

  unsigned long hex4() {
    unsigned long v = 0;
    for (int k = 0; k < 4 && !end(); ++k, ++at) {
      const char h = s_[at];
      const int d = h >= '0' && h <= '9' ? h - '0' : h >= 'a' && h <= 'f' ? h - 'a' + 10 : h >= 'A' && h <= 'F' ? h - 'A' + 10 : -1;
      if (d < 0) break;
      v = v * 16 + unsigned(d);
    }
    return v;
  }
};

// The offset of the member `key` of the object starting at scan.at (the last occurrence), or
// npos; on success scan.at is at the value.
std::size_t findMember(Scan& scan, const std::string& key) {
  std::size_t found = std::string::npos;
  ++scan.at;  // '{'
  while (true) {
    scan.space();
    if (scan.peek() != '"') break;
    const std::string k = scan.string();
    scan.space();
    if (scan.peek() != ':') break;
    ++scan.at;
    scan.space();
    if (k == key) found = scan.at;
    scan.skipValue();
    scan.space();
    if (scan.peek() != ',') break;
    ++scan.at;
  }
  if (found != std::string::npos) scan.at = found;
  return found;
}

// The offset of element `index` of the array starting at scan.at, or npos.
std::size_t findElement(Scan& scan, const std::string& token) {
  if (token.empty() || token.size() > 18 || !std::all_of(token.begin(), token.end(), [](char c) { return c >= '0' && c <= '9'; }))
    return std::string::npos;
  const unsigned long long index = std::stoull(token);
  ++scan.at;  // '['
  for (unsigned long long i = 0;; ++i) {
    scan.space();
    if (scan.end() || scan.peek() == ']') return std::string::npos;
    if (i == index) return scan.at;
    scan.skipValue();
    scan.space();
    if (scan.peek() != ',') return std::string::npos;
    ++scan.at;
  }
}

}  // namespace

TextPosition textPosition(const std::string& text, std::size_t offset) {
  TextPosition p;
  const std::size_t end = std::min(offset, text.size());
  for (std::size_t i = 0; i < end; ++i) {
    if (text[i] == '\n') {
      ++p.line;
      p.column = 1;
    } else {
      ++p.column;
    }
  }
  return p;
}

std::size_t jsonPointerOffset(const std::string& text, const std::string& pointer) {
  Scan scan(text);
  scan.space();
  std::size_t value = scan.at;
  for (const std::string& token : pointerTokens(pointer)) {
    const char c = scan.peek();
    const std::size_t next = c == '{' ? findMember(scan, token) : c == '[' ? findElement(scan, token) : std::string::npos;
    if (next == std::string::npos) break;
    scan.at = value = next;
  }
  return value;
}

std::string withTextPosition(const std::string& problem, const std::string& text, const std::string& pointer) {
  const TextPosition p = textPosition(text, jsonPointerOffset(text, pointer));
  return problem + " (line " + std::to_string(p.line) + ", column " + std::to_string(p.column) + ")";
}

}  // namespace qacc
