// What travels on the channels of hw-cycle's CSG pass (engines/csg_cycle_pass.h): a
// (leaf, pixel) evaluation of one job (a csg object in one tile, engines/csg_tile.h), by
// its place in the job's record, or the job's end marker, one per pipeline.
#pragma once
#include "hw_model/datapath/csg_interval_list.h"  // kCsgListBuffers

namespace qacc {

struct CsgToken {
  int job = 0;
  int index = -1;  // into CsgJob::issued; -1: the end of the job on this pipeline
};

}  // namespace qacc
