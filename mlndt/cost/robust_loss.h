#pragma once

// Robust losses on the per-point score s = ||W e||^2 (Eq. 10). NONE is the
// paper's plain sum. The scale is a Mahalanobis distance: HUBER and CAUCHY
// down-weight points whose sqrt(s) exceeds it.

#include <ceres/loss_function.h>

#include <string>

namespace mlndt {

class EnumTable;

enum class LossType {
  NONE,
  HUBER,
  CAUCHY,
};

// The names of LossType's values (enum_table.h).
const EnumTable& LossTypeTable();
const char* LossTypeToString(LossType type);
bool StringToLossType(std::string value, LossType* type);

// A new loss (caller or Problem takes ownership); nullptr for NONE.
ceres::LossFunction* CreateLoss(LossType type, double scale);

// rho(s) and rho'(s) of the loss, for the hand-written backends and reports.
// s is the squared residual norm.
void EvaluateLoss(
    LossType type, double scale, double s, double* rho, double* rho_prime);

}  // namespace mlndt
