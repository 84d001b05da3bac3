// A structure-aware mutation for the JSON inputs of the fuzz targets (libFuzzer's
// LLVMFuzzerCustomMutator). libFuzzer's byte mutations break the JSON of nearly every input:
// in a 1 200 s run of fuzz_render they left 1 000 of 290 585 inputs that the loader accepted.
// Here three mutations in four parse the input, change one value of the document (a number
// scaled, negated, zeroed or pushed to an extreme; a string swapped for a word of the format;
// a key removed or renamed; an array element duplicated or removed; a value of another type)
// and write it back, so most inputs stay JSON and reach the checks behind the parser. The
// fourth, and any input that does not parse, takes libFuzzer's own mutation, which keeps the
// parser itself fuzzed.
#pragma once
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

extern "C" std::size_t LLVMFuzzerMutate(std::uint8_t* data, std::size_t size, std::size_t max_size);

namespace qacc::fuzz {

inline void collectValues(nlohmann::json& j, std::vector<nlohmann::json*>& out) {
  // Iterative: a deeply nested input must not overflow the stack.
  std::vector<nlohmann::json*> todo{&j};
  while (!todo.empty() && out.size() < 100000) {
    nlohmann::json* v = todo.back();
    todo.pop_back();
    out.push_back(v);
    if (v->is_structured())
      for (auto& child : *v) todo.push_back(&child);
  }
}

// The quoted words of a libFuzzer dictionary (fuzz/*.dict: `name="word"` per line), the keys and
// value words of the format; a word list of one empty string when the file cannot be read.
inline std::vector<std::string> dictionaryWords(const char* path) {
  std::vector<std::string> words;
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) {
    const std::size_t a = line.find('"'), b = line.rfind('"');
    if (line.empty() || line[0] == '#' || a == std::string::npos || b <= a) continue;
    // The entry's bytes, unescaped; a key entry ("\"radius\":") gives its key.
    std::string w;
    for (std::size_t i = a + 1; i < b; ++i) {
      if (line[i] == '\\' && i + 1 < b) ++i;
      w += line[i];
    }
    if (!w.empty() && w.back() == ':') w.pop_back();
    if (w.size() >= 2 && w.front() == '"' && w.back() == '"') w = w.substr(1, w.size() - 2);
    words.push_back(w);
  }
  if (words.empty()) words.push_back("");
  return words;
}

inline std::size_t mutateJson(std::uint8_t* data, std::size_t size, std::size_t max_size, unsigned seed,
                              const std::vector<std::string>& words) {
  std::mt19937 rng(seed);
  auto pick = [&](std::size_t n) { return std::size_t(rng() % n); };
  if (pick(4) == 0) return LLVMFuzzerMutate(data, size, max_size);
  nlohmann::json doc = nlohmann::json::parse(data, data + size, nullptr, false);
  if (doc.is_discarded()) return LLVMFuzzerMutate(data, size, max_size);
  std::vector<nlohmann::json*> values;
  collectValues(doc, values);
  nlohmann::json& v = *values[pick(values.size())];
  static const double kFactors[] = {-1, 0, 0.5, 2, 10, 1e-3, 1e3, 1e-9, 1e9, 1e300, -1e300, 1e-300};
  switch (v.type()) {
    case nlohmann::json::value_t::number_integer:
    case nlohmann::json::value_t::number_unsigned:
    case nlohmann::json::value_t::number_float: {
      const double x = v.get<double>();
      switch (pick(3)) {
        case 0: v = x * kFactors[pick(std::size(kFactors))]; break;
        case 1:  // a nearby whole number (a number past 2^53 stays as it is, plus the step)
          v = std::fabs(x) < 9e15 ? double((long long)(x) + (long long)(pick(7)) - 3) : x + double(pick(7)) - 3;
          break;
        default: v = std::uniform_real_distribution<double>(-4, 4)(rng); break;
      }
      break;
    }
    case nlohmann::json::value_t::string:
      v = words[pick(words.size())];
      break;
    case nlohmann::json::value_t::boolean:
      v = !v.get<bool>();
      break;
    case nlohmann::json::value_t::array:
      if (!v.empty() && pick(2) == 0) v.erase(pick(v.size()));
      else if (!v.empty()) v.push_back(v[pick(v.size())]);
      else v.push_back(0);
      break;
    case nlohmann::json::value_t::object:
      if (!v.empty()) {
        auto it = v.begin();
        std::advance(it, pick(v.size()));
        const std::string key = it.key();
        nlohmann::json value = *it;
        v.erase(key);
        if (pick(2) == 0) v[words[pick(words.size())]] = std::move(value);  // renamed
      }
      break;
    default:
      v = words[pick(words.size())];
      break;
  }
  if (pick(8) == 0) v = pick(2) ? nlohmann::json::array({1, 2, 3}) : nlohmann::json(nullptr);  // another type
  const std::string text = doc.dump();
  if (text.size() > max_size) return LLVMFuzzerMutate(data, size, max_size);
  std::memcpy(data, text.data(), text.size());
  return text.size();
}

}  // namespace qacc::fuzz
