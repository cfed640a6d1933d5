#include "mlndt/cost/robust_loss.h"

#include <cmath>

#include "mlndt/common/enum_table.h"

namespace mlndt {

const EnumTable& LossTypeTable() {
  static const EnumTable table({
      {static_cast<int>(LossType::NONE), "NONE"},
      {static_cast<int>(LossType::HUBER), "HUBER"},
      {static_cast<int>(LossType::CAUCHY), "CAUCHY"},
  });
  return table;
}

const char* LossTypeToString(LossType type) {
  return EnumToString(LossTypeTable(), type);
}

bool StringToLossType(std::string value, LossType* type) {
  return StringToEnum(LossTypeTable(), std::move(value), type);
}

ceres::LossFunction* CreateLoss(LossType type, double scale) {
  switch (type) {
    case LossType::NONE:
      return nullptr;
    case LossType::HUBER:
      return new ceres::HuberLoss(scale);
    case LossType::CAUCHY:
      return new ceres::CauchyLoss(scale);
  }
  return nullptr;
}

void EvaluateLoss(
    LossType type, double scale, double s, double* rho, double* rho_prime) {
  const double b = scale * scale;
  switch (type) {
    case LossType::NONE:
      *rho = s;
      *rho_prime = 1.0;
      return;
    case LossType::HUBER:  // Same as ceres::HuberLoss.
      if (s > b) {
        const double r = std::sqrt(s);
        *rho = 2.0 * scale * r - b;
        *rho_prime = scale / r;
      } else {
        *rho = s;
        *rho_prime = 1.0;
      }
      return;
    case LossType::CAUCHY:  // Same as ceres::CauchyLoss.
      *rho = b * std::log1p(s / b);
      *rho_prime = 1.0 / (1.0 + s / b);
      return;
  }
}

LossSum::LossSum(LossType type, double scale)
    : type_(type), scale_(scale), b_(scale * scale) {}

void LossSum::Renormalise() {
  int exponent = 0;
  product_ = std::frexp(product_, &exponent);
  exponent_ += exponent;
}

double LossSum::Total() const {
  if (type_ != LossType::CAUCHY) return sum_;
  return b_ * (std::log(product_) + static_cast<double>(exponent_) * M_LN2);
}

}  // namespace mlndt
