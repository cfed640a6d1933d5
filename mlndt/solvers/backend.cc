#include "mlndt/solvers/backend.h"

#include "mlndt/common/enum_table.h"

namespace mlndt {

const EnumTable& BackendTypeTable() {
  static const EnumTable table(
      {
          {static_cast<int>(BackendType::CERES), "CERES"},
          {static_cast<int>(BackendType::NEWTON), "NEWTON"},
          {static_cast<int>(BackendType::LEVENBERG_MARQUARDT),
           "LEVENBERG_MARQUARDT"},
      },
      {{static_cast<int>(BackendType::LEVENBERG_MARQUARDT), "LM"}});
  return table;
}

const char* BackendTypeToString(BackendType type) {
  return EnumToString(BackendTypeTable(), type);
}

bool StringToBackendType(std::string value, BackendType* type) {
  return StringToEnum(BackendTypeTable(), std::move(value), type);
}

StageEnd StageControl::EndAfter(double step_norm,
                                bool step_is_successful) const {
  if (step_is_successful && step_tolerance > 0.0 &&
      step_norm < step_tolerance) {
    return StageEnd::CONVERGED;
  }
  if (!step_is_successful &&
      (end_on_rejected_step || step_norm < rejected_step_tolerance)) {
    return StageEnd::LAYER_MINIMUM;
  }
  return StageEnd::NONE;
}

void EndStage(StageEnd end, StageSummary* summary) {
  if (end == StageEnd::NONE) return;
  summary->termination_type = TerminationType::CONVERGENCE;
  summary->message =
      end == StageEnd::CONVERGED
          ? "update norm below tolerance"
          : "rejected step: the layer's minimum at its resolution";
}

}  // namespace mlndt
