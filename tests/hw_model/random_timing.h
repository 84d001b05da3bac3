// Every timing key of a configuration (isHwTimingKey) drawn at random, over the ranges the
// engine tests use: bus, FIFOs, setup units, pipelines, clip evaluators, radices, shading
// interval and latency, Z-buffer banks (shared between pipelines or not) and latencies, CSG
// tile pruning, the hierarchical Z unit's tiles and depth bits, and the clock.
#pragma once
#include <random>

#include "hw_model/config/hw_config.h"

inline qacc::HwConfig randomTiming(qacc::HwConfig cfg, std::mt19937& rng) {
  const auto pick = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
  cfg.clock_mhz = 25.0 * pick(1, 4);
  cfg.bus_width_bits = 16 << pick(0, 2);
  cfg.bus_cycles_per_word = pick(1, 3);
  cfg.descriptor_word_bits = 8 * pick(2, 8);
  cfg.host_fifo_depth = pick(1, 4);
  cfg.setup_mad_units = pick(1, 8);
  cfg.setup_fifo_depth = pick(1, 3);
  cfg.pipelines = pick(1, 4);
  cfg.pixel_fifo_depth = pick(1, 8);
  cfg.clip_evaluators = pick(1, 4);
  cfg.sqrt_radix = 2 << pick(0, 1);
  cfg.divider_radix = 2 << pick(0, 1);
  cfg.shading_cycles_per_pixel = pick(1, 4);
  cfg.shading_latency = pick(1, 20);
  cfg.zbuffer_banks = pick(1, 8);
  cfg.zbuffer_read_latency = pick(1, 4);
  cfg.zbuffer_bank_busy = pick(1, 4);
  cfg.csg_tile_pruning = pick(0, 1) == 1;
  cfg.hiz_tile_size = 4 << pick(0, 3);
  cfg.hiz_depth_bits = pick(8, 16);
  return cfg;
}
