#include "mlndt/solvers/backend_factory.h"

#include "mlndt/common/internal/check_option.h"

namespace mlndt {

bool BackendOptions::IsValid(std::string* error) const {
  MLNDT_OPTION_ENUM(type, BackendTypeToString);
  return ceres.IsValid(error) && newton.IsValid(error) &&
         levenberg_marquardt.IsValid(error);
}

std::unique_ptr<Backend> CreateBackend(const BackendOptions& options,
                                       std::string* error) {
  if (!options.IsValid(error)) return nullptr;
  switch (options.type) {
    case BackendType::CERES:
      return std::make_unique<CeresBackend>(options.ceres);
    case BackendType::NEWTON:
      return std::make_unique<NewtonBackend>(options.newton);
    case BackendType::LEVENBERG_MARQUARDT:
      return std::make_unique<LevenbergMarquardtBackend>(
          options.levenberg_marquardt);
  }
  *error = "unknown backend";
  return nullptr;
}

}  // namespace mlndt
