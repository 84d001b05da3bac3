// ViewCullCount: a modeler's account of the pieces it did not build because their
// conservative bounds miss the view volume (loader/view_culling.h, ObjectContext::view).
// `keep(mayBeSeen)` counts one piece and says whether to build it; `note()` is the phrase
// the modeler adds to its object's note (qacc info), empty when there was no view.
#pragma once
#include <cstddef>
#include <string>

namespace qacc {

struct ViewCullCount {
  bool active = false;      // a view was given: pieces were tested
  std::size_t pieces = 0;   // pieces tested
  std::size_t skipped = 0;  // of them, outside the view and not built

  explicit ViewCullCount(bool hasView) : active(hasView) {}
  bool keep(bool mayBeSeen) {
    ++pieces;
    skipped += !mayBeSeen;
    return mayBeSeen;
  }
  std::string note() const {
    if (!active) return {};
    return std::to_string(skipped) + " of " + std::to_string(pieces) + " pieces outside the view not built";
  }
};

}  // namespace qacc
