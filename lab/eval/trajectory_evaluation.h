#pragma once

// One estimated trajectory scored against a reference (what mlndt_eval
// reports): the poses paired by index or by time stamp
// (trajectory_association.h), then the ATE after an alignment and the RPE
// over `delta` frames (trajectory_metrics.h) and the KITTI devkit's segment
// errors (kitti_segment_errors.h).

#include <string>
#include <vector>

#include "lab/eval/kitti_segment_errors.h"
#include "lab/eval/trajectory.h"
#include "lab/eval/trajectory_io.h"
#include "lab/eval/trajectory_metrics.h"
#include "mlndt/common/result_table.h"

namespace mlndt {

// How the poses of the two trajectories are paired.
enum class PoseAssociation {
  AUTO,       // By time stamp when both have stamps, else by index.
  INDEX,      // Pose k with pose k (the common prefix).
  TIMESTAMP,  // Nearest stamps within max_time_difference_s.
};

const char* PoseAssociationToString(PoseAssociation association);
bool StringToPoseAssociation(const std::string& value,
                             PoseAssociation* association);

struct TrajectoryEvaluationOptions {
  TrajectoryAlignment alignment = TrajectoryAlignment::SE3;
  int delta = 1;  // RPE: frames between the two poses of a motion, >= 1.
  PoseAssociation association = PoseAssociation::AUTO;
  double max_time_difference_s = 0.02;  // TIMESTAMP: largest |dt|, > 0.
  KittiSegmentOptions segments;

  // The ranges and enum values of TrajectoryEvaluationOptionsTable (the
  // segments' too); false with *error naming the field.
  bool IsValid(std::string* error) const;
};

// The reference every estimate is scored against.
struct EvaluationReference {
  std::string path;
  TrajectoryFormat format = TrajectoryFormat::KITTI;
  Trajectory trajectory;
  bool timed = false;  // Its stamps are times (not scan indices).
};

struct TrajectoryEvaluation {
  std::string file;  // The estimate's file (its path).
  TrajectoryFormat format = TrajectoryFormat::KITTI;
  std::string association;  // "index" or "timestamp": as paired.
  size_t poses = 0;
  size_t pairs = 0;
  double path_length_m = 0.0;  // Of the reference over the pairs.
  AteSummary ate;
  RpeSummary rpe;
  size_t rpe_pairs = 0;  // 0: fewer than delta + 1 pairs, no RPE.
  KittiSegmentSummary kitti;
};

// TrajectoryEvaluation's fields (result_table.h), the ATE, RPE and KITTI
// summaries nested: mlndt_eval's "estimates" and docs/json_schema.md come
// from it.
const ResultTable& TrajectoryEvaluationTable();

// The files of an evaluation (mlndt_eval's flags of the same names).
struct TrajectoryFiles {
  std::string reference;
  bool detect_reference = true;  // Else reference_format.
  TrajectoryFormat reference_format = TrajectoryFormat::KITTI;
  std::string reference_calib;  // KITTI calib.txt: cam0 poses -> Velodyne.
  std::string reference_times;  // Stamps of a KITTI reference.
  std::vector<std::string> estimates;
  bool detect_estimate = true;  // Else estimate_format.
  TrajectoryFormat estimate_format = TrajectoryFormat::KITTI;
};

// Reads the reference (converted, stamped) and every estimate; results get
// each estimate's file and format. False with *error, naming the file and
// the flag, on anything that cannot be evaluated (CheckIndexPairing).
bool ReadTrajectoryFiles(const TrajectoryEvaluationOptions& options,
                         const TrajectoryFiles& files,
                         EvaluationReference* reference,
                         std::vector<Trajectory>* estimates,
                         std::vector<TrajectoryEvaluation>* results,
                         std::string* error);

// Reads a trajectory file, its format detected (`detect`) or `given`; with
// a KITTI calib.txt (`calib` not empty) the camera (cam0) poses are
// converted into the Velodyne frame with its Tr line.
bool ReadEvaluationTrajectory(const std::string& path,
                              bool detect,
                              TrajectoryFormat given,
                              const std::string& calib,
                              Trajectory* trajectory,
                              TrajectoryFormat* format,
                              std::string* error);

// Stamps the poses of `trajectory` with the stamps of `times_path` (one per
// pose, scan_times.h); false when the counts differ.
bool StampTrajectory(const std::string& times_path,
                     Trajectory* trajectory,
                     std::string* error);

// False with *error (naming the estimate's file) when AUTO would pair by
// index two trajectories of different lengths (also when one is timed and
// the other stamped with scan indices, a TUM file too): INDEX evaluates
// the common prefix only when asked for.
bool CheckIndexPairing(const TrajectoryEvaluationOptions& options,
                       const EvaluationReference& reference,
                       const std::string& path,
                       TrajectoryFormat format,
                       const Trajectory& estimate,
                       std::string* error);

// Scores `estimate`, read from result->file in result->format. False with
// *error when TIMESTAMP lacks stamps, no pose pairs up, or a metric fails.
bool EvaluateTrajectory(const TrajectoryEvaluationOptions& options,
                        const EvaluationReference& reference,
                        const Trajectory& estimate,
                        TrajectoryEvaluation* result,
                        std::string* error);

}  // namespace mlndt
