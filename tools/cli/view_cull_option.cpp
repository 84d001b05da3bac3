#include "tools/cli/view_cull_option.h"

namespace qacc {

void addViewCullOption(CLI::App* cmd, bool& enabled) {
  cmd->add_flag("!--no-view-cull", enabled,
                "Model every piece, also those whose bounds miss the view (default: pieces outside the view "
                "are not built)");
}

}  // namespace qacc
