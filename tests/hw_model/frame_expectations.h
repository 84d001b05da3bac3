// What the accelerator's tests expect of two frame buffers that must be bit-identical (hw
// against hw-cycle, a unit on against off, thread counts): same size, colour, object and
// primitive ids and depths, each difference named.
#pragma once
#include <string>

#include <gtest/gtest.h>

#include "raster/image/frame_buffer.h"

inline void expectIdentical(const qacc::FrameBuffer& a, const qacc::FrameBuffer& b, const std::string& what) {
  ASSERT_EQ(a.width, b.width);
  ASSERT_EQ(a.height, b.height);
  EXPECT_TRUE(a.color.data == b.color.data) << what << ": colour differs";
  EXPECT_TRUE(a.object == b.object) << what << ": object ids differ";
  EXPECT_TRUE(a.primitive == b.primitive) << what << ": primitive ids differ";
  EXPECT_TRUE(a.depth == b.depth) << what << ": depth differs";
}
