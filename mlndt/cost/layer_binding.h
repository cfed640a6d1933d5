#pragma once

// The layer a set of residuals scores against, switchable after the residuals
// were built. ML-NDT moves the same sampled points from layer to layer
// (Table 1): a registration rebinds one LayerBinding at every stage instead of
// rebuilding a cost function per point per stage (mlndt_point_cost.h).
//
// Lifetime: cost functors keep a pointer to the binding, which must outlive
// them; the bound layer must outlive every evaluation made while bound.

#include "mlndt/grid/ndt_layer.h"

namespace mlndt {

// Not copyable: functors point at the binding itself, so a copy (or a move
// into a container) would leave them bound to the old object. Temporaries
// are rejected at compile time for the same reason.
class LayerBinding {
 public:
  explicit LayerBinding(const NdtLayer& layer) : layer_(&layer) {}
  explicit LayerBinding(NdtLayer&&) = delete;
  LayerBinding(const LayerBinding&) = delete;
  LayerBinding& operator=(const LayerBinding&) = delete;

  // `point_stride`: consumers that can thin their points (MlNdtPairFactor)
  // use every point_stride-th on this layer, as Register does on coarse
  // layers (layer_scheduler.h); per-point cost functions ignore it. >= 1.
  void Rebind(const NdtLayer& layer, int point_stride = 1) {
    layer_ = &layer;
    point_stride_ = point_stride < 1 ? 1 : point_stride;
  }
  void Rebind(NdtLayer&&, int = 1) = delete;
  const NdtLayer& layer() const { return *layer_; }
  int point_stride() const { return point_stride_; }

 private:
  const NdtLayer* layer_;
  int point_stride_ = 1;
};

// Where a cost functor finds its layer: fixed, or through a binding. Converts
// implicitly from either, so Create(layer, ...) and Create(binding, ...) both
// read naturally.
class LayerSource {
 public:
  LayerSource(const NdtLayer& layer) : layer_(&layer) {}            // NOLINT
  LayerSource(const LayerBinding& binding) : binding_(&binding) {}  // NOLINT
  LayerSource(NdtLayer&&) = delete;  // A temporary layer would dangle.

  const NdtLayer& layer() const {
    return binding_ != nullptr ? binding_->layer() : *layer_;
  }
  // The binding's point stride; 1 for a fixed layer.
  int point_stride() const {
    return binding_ != nullptr ? binding_->point_stride() : 1;
  }

 private:
  const NdtLayer* layer_ = nullptr;
  const LayerBinding* binding_ = nullptr;
};

}  // namespace mlndt
