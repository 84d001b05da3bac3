// A comma-separated list of integers given on the command line (`--levels 2,4,8,16`):
// every item an integer in [lo, hi], or the option is refused with its name and the item.
#pragma once
#include <string>
#include <vector>

namespace qacc {

// Throws std::invalid_argument ("OPTION: 'ITEM' is not WHAT (an integer from LO to HI)").
std::vector<int> parseIntListOption(const std::string& text, const std::string& option, const std::string& what,
                                    int lo, int hi);

}  // namespace qacc
