// How the compare report writes numbers: JSON numbers with non-finite values as strings,
// and fixed or scientific text with "inf" / "n/a" for the tables and the CSV.
#pragma once
#include <string>

#include <nlohmann/json.hpp>

namespace qacc::compare {

nlohmann::json jnum(double v);            // "inf", "-inf", "nan" where not finite
std::string sci(double v);                // %.2e, "n/a" for NaN
std::string fmt(double v, int prec = 3);  // %.*f, "n/a" for NaN

}  // namespace qacc::compare
