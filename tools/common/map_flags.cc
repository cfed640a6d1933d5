#include "tools/common/map_flags.h"

#include <gflags/gflags.h>

#include "tools/common/registration_flags.h"

namespace mlndt {
namespace tools {
namespace {

const std::vector<std::string> kMapFlags = {"finest_cell_size",
                                            "num_layers",
                                            "division_constant",
                                            "min_points_per_cell",
                                            "min_eigenvalue",
                                            "min_eigenvalue_ratio",
                                            "coarse_weighting"};

// The shared flags a localizer (a map file, ML-NDT) refuses: the map's and
// conventional NDT's.
const std::vector<std::string> kLocalizerRefusedFlags = {"finest_cell_size",
                                                         "num_layers",
                                                         "division_constant",
                                                         "min_points_per_cell",
                                                         "min_eigenvalue",
                                                         "min_eigenvalue_ratio",
                                                         "coarse_weighting",
                                                         "ndt_cell_size",
                                                         "ndt_outlier_ratio",
                                                         "ndt_neighbors",
                                                         "ndt_max_iterations",
                                                         "ndt_max_step"};

// The shared registration flags a map build does not read (--threads and
// --preset it does).
const std::vector<std::string> kRegistrationOnlyFlags = {
    "method",
    "ndt_cell_size",
    "ndt_outlier_ratio",
    "ndt_neighbors",
    "ndt_max_iterations",
    "ndt_max_step",
    "backend",
    "sampling",
    "random_fraction",
    "gbs_cell_size",
    "start_layer",
    "iterations_per_layer",
    "max_iterations",
    "step_tolerance",
    "coarse_step_tolerance",
    "max_coarse_point_stride",
    "unmatched",
    "loss",
    "loss_scale",
    "linear_solver",
    "trust_region",
    "seed",
    "initial_uncertainty",
    "quality_check",
    "min_inlier_fraction",
    "max_mean_score",
    "inlier_gate",
    "min_constraint_ratio",
    "retry_yaw_seeds"};

}  // namespace

bool GridOptionsFromFlags(const std::string& tool,
                          LayeredGridOptions* grid,
                          std::string* error) {
  if (!RefuseGivenFlags(kRegistrationOnlyFlags,
                        "does not apply to " + tool +
                            " (it builds a map; registration flags belong "
                            "to mlndt_localize)",
                        error)) {
    return false;
  }
  if (FLAGS_preset == "paper") {
    *grid = PaperLayeredGridOptions();
  } else if (FLAGS_preset == "default") {
    *grid = LayeredGridOptions();
  } else {
    *error = "--preset=" + FLAGS_preset + ": expected default or paper";
    return false;
  }
  if (FlagGiven("num_layers")) grid->num_layers = FLAGS_num_layers;
  if (FlagGiven("division_constant")) {
    grid->division_constant = FLAGS_division_constant;
  }
  if (FlagGiven("finest_cell_size")) {
    grid->finest_cell_size_m = FLAGS_finest_cell_size;
  }
  if (FlagGiven("num_layers") && grid->finest_cell_size_m > 0.0) {
    *error =
        "--num_layers is ignored while --finest_cell_size > 0 (n is derived "
        "from it): give --finest_cell_size=0 with --num_layers";
    return false;
  }
  if (FlagGiven("coarse_weighting") &&
      !StringToCoarseWeighting(FLAGS_coarse_weighting,
                               &grid->coarse_weighting)) {
    *error = "--coarse_weighting=" + FLAGS_coarse_weighting +
             ": expected points or finest_cells";
    return false;
  }
  if (FlagGiven("min_points_per_cell")) {
    grid->min_points_per_cell = FLAGS_min_points_per_cell;
  }
  if (FlagGiven("min_eigenvalue")) {
    grid->regularization.min_eigenvalue_m2 = FLAGS_min_eigenvalue;
  }
  if (FlagGiven("min_eigenvalue_ratio")) {
    grid->regularization.min_eigenvalue_ratio = FLAGS_min_eigenvalue_ratio;
  }
  std::string why;
  if (!grid->IsValid(&why)) {
    // Name the flag behind the option.
    static const std::vector<std::pair<std::string, std::string>> kNames = {
        {"division_constant", "--division_constant"},
        {"num_layers", "--num_layers"},
        {"finest_cell_size_m", "--finest_cell_size"},
        {"min_points_per_cell", "--min_points_per_cell"},
        {"min_eigenvalue_ratio", "--min_eigenvalue_ratio"},
        {"min_eigenvalue_m2", "--min_eigenvalue"}};
    for (const auto& [option, flag] : kNames) {
      if (why.find(option) != std::string::npos) {
        *error = flag + ": " + why;
        return false;
      }
    }
    *error = why;
    return false;
  }
  return true;
}

const std::vector<std::string>& MapBuildRefusedFlags() {
  return kRegistrationOnlyFlags;
}

const std::vector<std::string>& LocalizerRefusedFlags() {
  return kLocalizerRefusedFlags;
}

bool RefuseMapFlags(const std::string& tool, std::string* error) {
  return RefuseGivenFlags(kMapFlags,
                          "does not apply to " + tool +
                              ": the map file fixes the cells (build the map "
                              "with mlndt_map to change them)",
                          error);
}

}  // namespace tools
}  // namespace mlndt
