#include "mlndt/solvers/backend_factory.h"

#include "mlndt/common/internal/check_option.h"
#include "mlndt/common/option_table.h"

namespace mlndt {

const OptionTable& BackendOptionsTable() {
  using S = BackendOptions;
  static const OptionTable table =
      OptionTableBuilder<S>("BackendOptions")
          .Enum("type",
                &S::type,
                BackendTypeTable(),
                "Which minimiser (\"lm\" names LEVENBERG_MARQUARDT).")
          .Struct("ceres",
                  &S::ceres,
                  CeresBackendOptionsTable(),
                  "Options of type CERES.")
          .Struct("newton",
                  &S::newton,
                  NewtonOptionsTable(),
                  "Options of type NEWTON.")
          .Struct("levenberg_marquardt",
                  &S::levenberg_marquardt,
                  LevenbergMarquardtOptionsTable(),
                  "Options of type LEVENBERG_MARQUARDT.")
          .Validator(&S::IsValid)
          .Build();
  return table;
}

bool BackendOptions::IsValid(std::string* error) const {
  return BackendOptionsTable().Check(*this, error) && ceres.IsValid(error) &&
         newton.IsValid(error) && levenberg_marquardt.IsValid(error);
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
