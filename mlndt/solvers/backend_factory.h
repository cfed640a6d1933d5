#pragma once

// Which backend minimises the objective, with every backend's options, and
// the factory that makes it (the shape of ceres' TrustRegionStrategy::Create).

#include <memory>
#include <string>

#include "mlndt/solvers/backend.h"
#include "mlndt/solvers/ceres_backend.h"
#include "mlndt/solvers/levenberg_marquardt_backend.h"
#include "mlndt/solvers/newton_backend.h"

namespace mlndt {

class OptionTable;

struct BackendOptions {
  BackendType type = BackendType::CERES;
  CeresBackendOptions ceres;                      // type CERES.
  NewtonOptions newton;                           // type NEWTON.
  LevenbergMarquardtOptions levenberg_marquardt;  // type LEVENBERG_MARQUARDT.

  // Checks `type` and the options of every backend.
  bool IsValid(std::string* error) const;
};

// BackendOptions's fields: name, unit, valid range and help (option_table.h).
const OptionTable& BackendOptionsTable();

// A new backend of options.type; nullptr with *error for invalid options.
std::unique_ptr<Backend> CreateBackend(const BackendOptions& options,
                                       std::string* error);

}  // namespace mlndt
