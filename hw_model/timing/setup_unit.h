// SetupUnit: per primitive (design §3.2 step 2), in the setup processor's floating point:
// transform to window space (raster/window_primitive.h), exact screen box, local origin
// at the box corner (small coordinates), the contour conic Δ = b² − ac, block-exponent
// normalisation (Q and kQ are the same surface), 1/a, interpolator seeds for Δ, b, c, the
// clip planes, their depths (caps) and the shading vectors; then quantisation of all of
// it to the configured formats (PrimitiveSetup). Its cost is its multiply-add count on
// `setup_mad_units` units; the primitive's descriptor arrives first over the host bus.
#pragma once
#include <Eigen/Dense>
#include <deque>

#include "hw_model/timing/fifo.h"
#include "hw_model/config/hw_config.h"
#include "hw_model/datapath/primitive_setup.h"
#include "hw_model/timing/unit.h"
#include "modeling/scene/scene.h"

namespace qacc {

class SetupUnit : public Unit {
 public:
  // The arithmetic (shared by both engines).
  static PrimitiveSetup run(const Scene& scene, int index, const Eigen::Matrix4d& M, const Eigen::Matrix4d& Minv,
                            const HwConfig& cfg, OverflowCounter& ovf);
  // Multiply-add operations of the setup of a primitive with `planes` clip planes and
  // `pointLights` point lights (see setup_unit.cpp for the breakdown).
  static int operationCount(int planes, int pointLights, bool facet);
  static int cycles(const PrimitiveSetup& s, const HwConfig& cfg);

  // Timing: takes primitive indices from `in`, holds each for cycles(), pushes to `out`.
  SetupUnit(const std::vector<PrimitiveSetup>& setups, const HwConfig& cfg, Fifo<int>& in, Fifo<int>& out)
      : Unit("setup"), setups_(setups), cfg_(cfg), in_(in), out_(out) {}
  bool tick(std::uint64_t now) override;
  std::uint64_t nextEvent() const override { return current_ >= 0 && readyAt_ > 0 ? readyAt_ : Unit::nextEvent(); }
  bool holdsWork() const override { return current_ >= 0; }

 private:
  const std::vector<PrimitiveSetup>& setups_;
  const HwConfig& cfg_;
  Fifo<int>& in_;
  Fifo<int>& out_;
  int current_ = -1;
  std::uint64_t readyAt_ = 0;
};

}  // namespace qacc
