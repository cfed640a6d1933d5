#include "mlndt/registration/registration_summary.h"

#include <cmath>
#include <iomanip>
#include <sstream>

#include "mlndt/common/pose.h"

namespace mlndt {

std::string RegistrationSummary::BriefReport() const {
  std::ostringstream out;
  out << algorithm
      << " registration: " << TerminationTypeToString(termination_type) << ", "
      << num_iterations << " iterations, score " << initial_score << " -> "
      << final_score << ", " << std::fixed << std::setprecision(1)
      << total_time_s * 1e3 << " ms";
  return out.str();
}

std::string RegistrationSummary::FullReport() const {
  std::ostringstream out;
  out << BriefReport() << "\n";
  out << "  message:        " << message << "\n";
  out << std::setprecision(4) << std::fixed;
  const Vector6d& xi = reference_from_input_xi;
  out << "  pose xi:        t = (" << xi(0) << ", " << xi(1) << ", " << xi(2)
      << ") m, "
      << "(alpha, beta, gamma) = (" << xi(3) * kRadToDeg << ", "
      << xi(4) * kRadToDeg << ", " << xi(5) * kRadToDeg << ") deg\n";
  out << "  layers:         start " << start_layer << " of " << num_layers
      << " (finest cell " << std::setprecision(2) << finest_cell_size_m
      << " m), iterations";
  for (size_t i = 0; i < iterations_per_layer.size(); ++i) {
    out << " L" << i + 1 << "=" << iterations_per_layer[i];
  }
  out << "\n  points:         " << input_points << " input, " << sampled_points
      << " sampled, " << matched_points << " matched, " << unmatched_points
      << " unmatched\n";
  if (quality.points > 0) {
    out << std::setprecision(3) << "  fit:            median distance "
        << quality.median_distance << ", inliers " << quality.inlier_fraction
        << ", mean score " << quality.mean_score << ", own cell "
        << quality.own_cell_fraction << ", constraint ratio "
        << constraints.constraint_ratio;
    if (constraints.flatness > 0.0) {
      out << ", flatness " << constraints.flatness;
    }
    if (attempts > 1) out << ", " << attempts << " attempts";
    out << "\n";
  }
  out << std::setprecision(2) << "  time [ms]:      map " << map_time_s * 1e3
      << ", sampling " << sampling_time_s * 1e3 << ", solve "
      << solve_time_s * 1e3 << ", total " << total_time_s * 1e3 << "\n";
  if (map_occupied_cells > 0) {
    out << std::setprecision(3) << "  map memory:     " << map_bytes / 1e6
        << " MB, " << map_occupied_cells << " occupied cells, "
        << std::setprecision(0)
        << static_cast<double>(map_bytes) / map_occupied_cells
        << " bytes per cell\n";
  }
  // A FAILURE has no solution, and a zero covariance is "not computed" (H
  // singular): neither is a sigma of 0. Infinite variances (degenerate
  // directions) are printed as inf.
  if (termination_type == TerminationType::FAILURE || covariance.isZero()) {
    out << "  sigma (cov):    not available\n";
    return out.str();
  }
  out << std::setprecision(4) << "  sigma (cov):    t = ("
      << std::sqrt(covariance(0, 0)) << ", " << std::sqrt(covariance(1, 1))
      << ", " << std::sqrt(covariance(2, 2)) << ") m, angles = ("
      << std::sqrt(covariance(3, 3)) * kRadToDeg << ", "
      << std::sqrt(covariance(4, 4)) * kRadToDeg << ", "
      << std::sqrt(covariance(5, 5)) * kRadToDeg << ") deg\n";
  return out.str();
}

}  // namespace mlndt
