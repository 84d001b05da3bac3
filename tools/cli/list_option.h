// A comma-separated list of numbers given on the command line (`--levels 2,4,8,16`,
// `--tolerances 4,2,1,0.5`): every item a number in [lo, hi], or the option is refused with
// its name and the item. One splitter serves both kinds; an empty item is refused.
#pragma once
#include <string>
#include <vector>

namespace qacc {

// Throws std::invalid_argument ("OPTION: 'ITEM' is not WHAT (an integer from LO to HI)").
std::vector<int> parseIntListOption(const std::string& text, const std::string& option, const std::string& what,
                                    int lo, int hi);

// Throws std::invalid_argument ("OPTION: 'ITEM' is not WHAT (a number from LO to HI)");
// NaN, infinities and hexadecimal forms are refused.
std::vector<double> parseDoubleListOption(const std::string& text, const std::string& option, const std::string& what,
                                          double lo, double hi);

}  // namespace qacc
