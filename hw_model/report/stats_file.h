// Statistics files: a JSON document and the same figures as one CSV row beside it
// (`--stats FILE` of every engine, the rows of `qacc sweep`). Nested objects flatten to
// dotted keys (`units.zbuffer.stall`); arrays of objects with a "name" flatten by name.
#pragma once
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace qacc {

// A number, or "inf" / "-inf" / "nan" (JSON has no non-finite numbers; PSNR of equal images is inf).
nlohmann::ordered_json jsonNumber(double v);
// The number jsonNumber wrote: a JSON number, or "inf" / "-inf" / "nan" as ±infinity / NaN;
// NaN for anything else (a missing figure).
double jsonNumberValue(const nlohmann::ordered_json& v);
// The leaves of `j` as dotted keys and their text (strings unquoted).
void flattenJson(const nlohmann::ordered_json& j, std::vector<std::string>& keys, std::vector<std::string>& values);
// One header line + one value line.
std::string jsonToCsvRow(const nlohmann::ordered_json& j);
// Writes `path` (JSON) and `path` with its extension replaced by .csv; throws on failure.
void writeStatsFiles(const std::string& path, const nlohmann::ordered_json& j);

// A table of rows (objects with the same flat keys): OUT.json ({"format", "rows"}) and
// OUT.csv (a header and one line per row); `out` may end in .json, .csv or neither.
void writeResultRows(const std::string& out, const std::string& format, const nlohmann::ordered_json& rows);

}  // namespace qacc
