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

  void Rebind(const NdtLayer& layer) { layer_ = &layer; }
  void Rebind(NdtLayer&&) = delete;
  const NdtLayer& layer() const { return *layer_; }

 private:
  const NdtLayer* layer_;
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

 private:
  const NdtLayer* layer_ = nullptr;
  const LayerBinding* binding_ = nullptr;
};

}  // namespace mlndt
