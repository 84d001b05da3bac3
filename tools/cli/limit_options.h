// The --max-* options of every command that loads a scene (modeling/support/limits.h):
// each raises one limit on the work a scene may ask for.
#pragma once
#include <CLI/CLI.hpp>

#include "modeling/support/limits.h"

namespace qacc {

// Adds --max-input-mb, --max-primitives, --max-cells and --max-triangles to `cmd`; they
// write into `limits`, which must outlive the parse (commands keep it in a shared_ptr).
void addLimitOptions(CLI::App* cmd, Limits& limits);

}  // namespace qacc
