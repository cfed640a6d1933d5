#pragma once

// The registrations behind mlndt_covariance: one pair registered from many
// perturbed starts, so that the spread of the estimates can be compared with
// the covariance each registration reports (covariance_consistency.h).

#include <functional>
#include <random>
#include <string>
#include <vector>

#include "lab/eval/covariance_consistency.h"
#include "mlndt/cloud/point_cloud.h"
#include "mlndt/registration/registration.h"

namespace mlndt {

struct CovarianceCampaignOptions {
  int starts = 20;                 // Registrations per pair, >= 2.
  double max_translation_m = 0.5;  // Start offsets uniform in +-this per axis.
  double max_rotation_deg = 5.0;   // ... and +-this per Euler angle.
  bool vary_sampling_seed = true;  // Start k samples with seed + k.
  // Runs farther than this from the pair's median estimate did not reach
  // the common optimum: counted as outliers and left out.
  double outlier_translation_m = 0.1;
  double outlier_rotation_deg = 1.0;
};

// The bundled KITTI frames of `dir` (data/kitti): pcd/000000.pcd to
// pcd/000007.pcd and their poses_velo.txt (world_from_scan).
bool ReadBundledKittiFrames(const std::string& dir,
                            std::vector<PointCloud>* scans,
                            std::vector<Isometry3d>* poses,
                            std::string* error);

// Called after start k (0-based) with its summary and whether it is usable
// (a usable solution with a covariance).
using CovarianceRunCallback =
    std::function<void(int k, const RegistrationSummary&, bool usable)>;

// Builds the reference's map and registers `input` from `starts` offsets
// drawn from *rng around reference_from_input; fills pair->reference_xi,
// runs, failures and outliers (pair->dataset and name are the caller's).
// False with *error when the map cannot be built.
bool RunCovariancePair(const CovarianceCampaignOptions& campaign,
                       const RegistrationOptions& options,
                       const PointCloud& reference,
                       const PointCloud& input,
                       const Isometry3d& reference_from_input,
                       std::mt19937_64* rng,
                       const CovarianceRunCallback& on_run,
                       PairRuns* pair,
                       std::string* error);

}  // namespace mlndt
