#include "hw_model/timing/shading_unit.h"

namespace qacc {

bool ShadingUnit::tick(std::uint64_t now) {
  (void)now;
  bool changed = false;
  while (stages_.done()) {
    ++delivered_;
    stages_.retire();
    changed = true;
  }
  if (stages_.canAccept() && in_.ready()) {
    stages_.accept({}, std::uint64_t(p_.cycles_per_pixel));
    in_.receive();
    countItem();
    changed = true;
  }
  if (changed || stages_.holdsWork()) countBusy();
  else countIdle();
  return changed;
}

}  // namespace qacc
