#pragma once

// Robust losses on the per-point score s = ||W e||^2 (Eq. 10). NONE is the
// paper's plain sum. The scale is a Mahalanobis distance: HUBER and CAUCHY
// down-weight points whose sqrt(s) exceeds it.

#include <ceres/loss_function.h>

#include <cstdint>
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

// sum_k rho(s_k) over many s_k, as EvaluateLoss sums them, with one log for
// CAUCHY instead of a log1p per point: b sum log(1 + s_k / b) is taken as
// b log(prod (1 + s_k / b)), the product kept as mantissa and binary
// exponent (renormalised at 2^500; it cannot overflow while a factor is
// below 2^523, far above a matched point's s).
class LossSum {
 public:
  LossSum(LossType type, double scale);
  // Adds rho(s) and returns rho'(s).
  double Add(double s) {
    if (type_ != LossType::CAUCHY) {
      double rho = 0.0, rho_prime = 1.0;
      EvaluateLoss(type_, scale_, s, &rho, &rho_prime);
      sum_ += rho;
      return rho_prime;
    }
    const double factor = 1.0 + s / b_;
    product_ *= factor;
    if (product_ >= 0x1p500) Renormalise();
    return 1.0 / factor;
  }
  double Total() const;

 private:
  void Renormalise();

  LossType type_;
  double scale_;
  double b_;  // scale^2.
  double sum_ = 0.0;
  double product_ = 1.0;
  int64_t exponent_ = 0;
};

}  // namespace mlndt
