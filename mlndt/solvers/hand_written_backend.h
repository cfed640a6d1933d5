#pragma once

// The shell of the hand-written backends, Newton (Section 4.1,
// newton_backend.h) and Levenberg-Marquardt (Section 4.2,
// levenberg_marquardt_backend.h): the problem kept from SetProblem, and per
// stage the points (every control.point_stride-th) and the ML-NDT objective
// on the stage's layer (Eq. 12), handed to the backend's minimiser.

#include <Eigen/Core>
#include <vector>

#include "mlndt/solvers/backend.h"
#include "mlndt/solvers/objective.h"

namespace mlndt {

class HandWrittenBackend : public Backend {
 public:
  void SetProblem(const std::vector<Eigen::Vector3d>& input_points,
                  const ObjectiveOptions& objective,
                  int num_threads) final;
  // CHECK-fails before SetProblem.
  void SolveStage(const NdtLayer& layer,
                  const StageControl& control,
                  Vector6d* reference_from_input_xi,
                  StageSummary* summary) final;

 protected:
  // `name` names the backend in the CHECK message.
  explicit HandWrittenBackend(const char* name) : name_(name) {}

  // Minimises `objective` from *xi for at most control.max_iterations
  // iterations, recording one IterationRecord per iteration.
  virtual void Minimize(const Objective& objective,
                        const StageControl& control,
                        Vector6d* reference_from_input_xi,
                        StageSummary* summary) const = 0;

 private:
  const char* name_;
  const std::vector<Eigen::Vector3d>* input_points_ = nullptr;
  ObjectiveOptions objective_;
  int num_threads_ = 1;
};

}  // namespace mlndt
