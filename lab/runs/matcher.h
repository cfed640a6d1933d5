#pragma once

// The choice of scan matcher for the pipeline and the tools: ML-NDT
// (registration/registration.h) or the conventional NDT baseline
// (ndt/ndt_registration.h), each with its own options, behind one call. The
// library's entry points stay separate; this is where a tool's --method
// switch lives.

#include <string>

#include "mlndt/cloud/point_cloud.h"
#include "mlndt/grid/layered_grid.h"
#include "mlndt/ndt/ndt_registration.h"
#include "mlndt/registration/registration.h"

namespace mlndt {

enum class Method {
  MLNDT,  // Layered map, Mahalanobis score (Section 4), layer schedule.
  NDT,    // Conventional NDT: one grid, Gaussian score (Section 3, Eq. 4).
};

const char* MethodToString(Method method);
// Case-insensitive; "ml-ndt" and "ml_ndt" name MLNDT.
bool StringToMethod(std::string value, Method* method);

struct MatcherOptions {
  Method method = Method::MLNDT;
  RegistrationOptions mlndt;  // Method MLNDT.
  NdtOptions ndt;             // Method NDT.

  // Checks the method and the options of the method chosen.
  bool IsValid(std::string* error) const;
};

// The map options the chosen method registers on, for `reference` (NDT's
// paper cell depends on the cloud's box). False with *error when there is
// none.
bool MatcherGridOptions(const MatcherOptions& options,
                        const PointCloud& reference,
                        LayeredGridOptions* grid_options,
                        std::string* error);

// Registers `input` on a map built with MatcherGridOptions.
void RegisterWithMatcher(const MatcherOptions& options,
                         const LayeredGrid& reference_map,
                         const PointCloud& input,
                         const Isometry3d& initial_reference_from_input,
                         RegistrationSummary* summary);

// Builds the map of `reference`, then registers.
void RegisterWithMatcher(const MatcherOptions& options,
                         const PointCloud& reference,
                         const PointCloud& input,
                         const Isometry3d& initial_reference_from_input,
                         RegistrationSummary* summary);

}  // namespace mlndt
