// mlndt_localize_starts: how honest map localisation's verdict is from
// perturbed starts. For N scans of a sequence (evenly spread over it) each
// scan's reference pose is moved by a seeded random offset of exactly
// --offset_m in a uniformly random direction and --offset_deg about a
// uniformly random axis (in the scan's frame); the scan is localised onto
// the map from there (Localizer::LocalizeFrom, localization_prior.h) and
// the result is counted right (within --tolerance_m / --tolerance_deg of
// the reference) or wrong against its verdict. The scans alternate between
// a TRAIN half (even positions) and a TEST half (odd positions): choose a
// setting on TRAIN, report TEST.
//
//   mlndt_localize_starts --map=livox.mlndt
//       --scans=$MLNDT_DATA_DIR/fastlio_avia_hku_2_sequence/pcd
//       --poses=$MLNDT_DATA_DIR/fastlio_avia_hku_2_sequence/odom_poses.txt
//       --num_scans=50 --offset_m=0.5 --offset_deg=10 --prior_scale=1.5
//
// --prior_scale=0 states no prior (the registration's verdict alone);
// otherwise the prior stated to the localiser is --prior_scale times the
// offset. Prints one line per scan and the counts per half; exit 0.

#include <gflags/gflags.h>
#include <glog/logging.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "lab/eval/pose_error.h"
#include "lab/eval/trajectory.h"
#include "lab/eval/trajectory_io.h"
#include "mlndt/cloud/io.h"
#include "mlndt/common/pose.h"
#include "mlndt/grid/grid_io.h"
#include "mlndt/pipeline/localization_prior.h"
#include "mlndt/pipeline/localizer.h"

// clang-format off
DEFINE_string(map, "", "The map (mlndt_map --output)");
DEFINE_string(scans, "", "Folder of the scans, NNNNNN.pcd by index");
DEFINE_string(poses, "", "Reference poses (KITTI or TUM), pose k for scan k");
DEFINE_int32(num_scans, 50, "Scans localised, spread evenly over the poses");
DEFINE_double(offset_m, 0.5, "Start offset from the reference [m]");
DEFINE_double(offset_deg, 10.0, "Start offset from the reference [deg]");
DEFINE_uint64(seed, 1, "Seed of the offsets");
DEFINE_double(prior_scale, 1.5, "Prior stated = this x the offset; 0 = none");
DEFINE_double(margin, 0.02, "PriorCheckOptions::ambiguity_inlier_margin");
DEFINE_double(min_fit_ratio, 0.95, "PriorCheckOptions::min_fit_ratio");
DEFINE_bool(explore, true, "PriorCheckOptions::explore");
DEFINE_double(tolerance_m, 0.2, "A result is right within this [m] ...");
DEFINE_double(tolerance_deg, 1.0, "... and this [deg] of the reference");
// clang-format on

namespace mlndt {
namespace {

// Exactly offset_m in a random direction, offset_deg about a random axis.
Isometry3d RandomOffset(std::mt19937_64* rng) {
  std::normal_distribution<double> normal;
  Eigen::Vector3d t(normal(*rng), normal(*rng), normal(*rng));
  Eigen::Vector3d axis(normal(*rng), normal(*rng), normal(*rng));
  Isometry3d offset = Isometry3d::Identity();
  offset.translation() = FLAGS_offset_m * t.normalized();
  offset.linear() =
      Eigen::AngleAxisd(FLAGS_offset_deg * kDegToRad, axis.normalized())
          .toRotationMatrix();
  return offset;
}

// tx,ty,tz,alpha,beta,gamma [m, deg] (R = Rx Ry Rz), to reproduce a start.
std::string OffsetText(const Isometry3d& offset) {
  const Vector6d xi = IsometryToPoseVector(offset);
  char text[160];
  std::snprintf(text,
                sizeof(text),
                "%.6f,%.6f,%.6f,%.6f,%.6f,%.6f",
                xi(0),
                xi(1),
                xi(2),
                xi(3) * kRadToDeg,
                xi(4) * kRadToDeg,
                xi(5) * kRadToDeg);
  return text;
}

// Counts of one half.
struct Counts {
  int scans = 0;
  int right_convergence = 0;
  int wrong_convergence = 0;
  int right_no_convergence = 0;
  int wrong_no_convergence = 0;
  int not_usable_right = 0;  // The result was right but flagged.
  int not_usable_wrong = 0;

  void Add(TerminationType type, bool right) {
    ++scans;
    if (type == TerminationType::CONVERGENCE) {
      ++(right ? right_convergence : wrong_convergence);
    } else if (type == TerminationType::NO_CONVERGENCE) {
      ++(right ? right_no_convergence : wrong_no_convergence);
    } else {
      ++(right ? not_usable_right : not_usable_wrong);
    }
  }
  void Print(const char* name) const {
    std::printf(
        "%-5s scans %2d: CONVERGENCE right %2d wrong %d; NO_CONVERGENCE "
        "right %d wrong %d; not usable %2d (of which right %d)\n",
        name,
        scans,
        right_convergence,
        wrong_convergence,
        right_no_convergence,
        wrong_no_convergence,
        not_usable_right + not_usable_wrong,
        not_usable_right);
  }
};

LocalizerOptions Options() {
  LocalizerOptions options;
  options.guess_translation_m = FLAGS_prior_scale * FLAGS_offset_m;
  options.guess_rotation_deg =
      std::min(180.0, FLAGS_prior_scale * FLAGS_offset_deg);
  options.prior_check.ambiguity_inlier_margin = FLAGS_margin;
  options.prior_check.min_fit_ratio = FLAGS_min_fit_ratio;
  options.prior_check.explore = FLAGS_explore;
  return options;
}

InitialGuessUncertainty Prior(const LocalizerOptions& options) {
  InitialGuessUncertainty prior;
  prior.given = FLAGS_prior_scale > 0.0;
  prior.translation_m = options.guess_translation_m;
  prior.rotation_deg = options.guess_rotation_deg;
  return prior;
}

int Run() {
  std::string error;
  LayeredGrid map;
  Trajectory poses;
  if (!LoadLayeredGrid(FLAGS_map, &map, &error) ||
      !ReadTrajectory(FLAGS_poses, &poses, &error)) {
    std::fprintf(stderr, "mlndt_localize_starts: %s\n", error.c_str());
    return 2;
  }
  const LocalizerOptions options = Options();
  CHECK(options.IsValid(&error)) << error;
  const size_t total = poses.poses().size();
  const SuccessCriterion tolerance{FLAGS_tolerance_m, FLAGS_tolerance_deg};
  Counts halves[2];
  std::printf(
      "pos  scan half  termination      error [m]  [deg]  moved [m] "
      "runs kept inliers\n");
  for (int i = 0; i < FLAGS_num_scans; ++i) {
    const size_t k = static_cast<size_t>(i) * total / FLAGS_num_scans;
    char name[32];
    std::snprintf(name, sizeof(name), "/%06zu.pcd", k);
    PointCloud scan;
    if (!ReadPointCloud(FLAGS_scans + name, &scan, nullptr, &error)) {
      std::fprintf(stderr, "mlndt_localize_starts: %s\n", error.c_str());
      return 1;
    }
    std::mt19937_64 rng(FLAGS_seed * 1000003u + k);
    const Isometry3d& truth = poses.poses()[k];
    const Isometry3d offset = RandomOffset(&rng);
    const Isometry3d guess = truth * offset;
    // What Localizer::LocalizeFrom runs, with the check's summary.
    RegistrationSummary summary;
    PriorCheckSummary check;
    RegisterWithinPrior(options.prior_check,
                        options.registration,
                        map,
                        scan,
                        guess,
                        Prior(options),
                        &summary,
                        &check);
    const TerminationType type = summary.termination_type;
    // The registration's own pose, used or not: is the verdict right?
    const Isometry3d& estimate = summary.reference_from_input;
    const PoseError e = ComputePoseError(truth, estimate);
    const bool right = tolerance.IsWithin(e);
    halves[i % 2].Add(type, right);
    std::printf(
        "%-4d %-4zu %-5s %-16s %9.3f %6.2f %9.3f %4d %4d %5.3f  %s  offset "
        "%s\n",
        i,
        k,
        i % 2 == 0 ? "train" : "test",
        TerminationTypeToString(type),
        e.translation_m,
        e.rotation_deg(),
        TranslationErrorM(guess, estimate),
        check.explored_starts,
        check.usable_within,
        summary.quality.inlier_fraction,
        right ? "right" : "WRONG",
        OffsetText(offset).c_str());
  }
  halves[0].Print("train");
  halves[1].Print("test");
  return 0;
}

}  // namespace
}  // namespace mlndt

int main(int argc, char** argv) {
  google::InitGoogleLogging(argv[0]);
  gflags::SetUsageMessage(
      "Counts right/wrong verdicts of map localisation from perturbed "
      "starts");
  gflags::ParseCommandLineFlags(&argc, &argv, true);
  if (FLAGS_map.empty() || FLAGS_scans.empty() || FLAGS_poses.empty() ||
      FLAGS_num_scans <= 0) {
    std::fprintf(stderr,
                 "mlndt_localize_starts: give --map, --scans, --poses and "
                 "--num_scans > 0\n");
    return 2;
  }
  return mlndt::Run();
}
