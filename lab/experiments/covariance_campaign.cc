#include "lab/experiments/covariance_campaign.h"

#include <cstdio>
#include <vector>

#include "lab/eval/statistics.h"
#include "mlndt/cloud/io.h"
#include "mlndt/cloud/pose_io.h"
#include "mlndt/common/pose.h"

namespace mlndt {
namespace {

// Leaves out runs that did not reach the common optimum (median per axis).
void KeepRunsNearTheMedian(const CovarianceCampaignOptions& campaign,
                           const std::vector<StartResult>& runs,
                           PairRuns* pair) {
  Vector6d median;
  for (int a = 0; a < 6; ++a) {
    std::vector<double> values;
    for (const StartResult& run : runs) values.push_back(run.xi(a));
    median(a) = ComputeStats(values).median;
  }
  for (const StartResult& run : runs) {
    const Vector6d d = run.xi - median;
    if (d.head<3>().norm() > campaign.outlier_translation_m ||
        d.tail<3>().norm() * kRadToDeg > campaign.outlier_rotation_deg) {
      ++pair->outliers;
    } else {
      pair->runs.push_back(run);
    }
  }
}

}  // namespace

bool ReadBundledKittiFrames(const std::string& dir,
                            std::vector<PointCloud>* scans,
                            std::vector<Isometry3d>* poses,
                            std::string* error) {
  if (!ReadKittiPoses(dir + "/poses_velo.txt", poses, error)) return false;
  for (int i = 0; i < 8; ++i) {
    char name[32];
    std::snprintf(name, sizeof(name), "/pcd/%06d.pcd", i);
    scans->emplace_back();
    if (!ReadPointCloud(dir + name, &scans->back(), nullptr, error)) {
      return false;
    }
  }
  return true;
}

bool RunCovariancePair(const CovarianceCampaignOptions& campaign,
                       const RegistrationOptions& options,
                       const PointCloud& reference,
                       const PointCloud& input,
                       const Isometry3d& reference_from_input,
                       std::mt19937_64* rng,
                       const CovarianceRunCallback& on_run,
                       PairRuns* pair,
                       std::string* error) {
  LayeredGrid map;
  if (!LayeredGrid::Build(options.grid, reference, &map, error)) return false;
  pair->reference_xi = IsometryToPoseVector(reference_from_input);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::vector<StartResult> runs;
  for (int k = 0; k < campaign.starts; ++k) {
    Vector6d offset;
    for (int a = 0; a < 3; ++a) {
      offset(a) = campaign.max_translation_m * unit(*rng);
    }
    for (int a = 3; a < 6; ++a) {
      offset(a) = campaign.max_rotation_deg * kDegToRad * unit(*rng);
    }
    RegistrationOptions start_options = options;
    if (campaign.vary_sampling_seed) {
      start_options.sampling.seed = options.sampling.seed + k;
    }
    RegistrationSummary summary;
    Register(start_options,
             map,
             input,
             PoseVectorToIsometry(offset) * reference_from_input,
             &summary);
    const bool usable =
        summary.IsSolutionUsable() && !summary.covariance.isZero(0.0);
    on_run(k, summary, usable);
    if (!usable) {
      ++pair->failures;
      continue;
    }
    StartResult run;
    run.xi = summary.reference_from_input_xi;
    run.covariance = summary.covariance;
    const double dof = 3.0 * static_cast<double>(summary.matched_points) - 6.0;
    run.sigma2 = dof > 0.0 ? summary.final_score / dof : 1.0;
    runs.push_back(run);
  }
  KeepRunsNearTheMedian(campaign, runs, pair);
  return true;
}

}  // namespace mlndt
