#include "lab/eval/trajectory_evaluation.h"

#include <algorithm>
#include <cctype>
#include <string>
#include <utility>
#include <vector>

#include "lab/eval/scan_times.h"
#include "lab/eval/trajectory_association.h"
#include "lab/eval/trajectory_evaluation_option_table.h"
#include "mlndt/cloud/pose_io.h"

namespace mlndt {
namespace {

// Whether an estimate read from `path` in `format` has time stamps: TUM,
// and its header does not say they are scan indices.
bool EstimateTimed(TrajectoryFormat format, const std::string& path) {
  return format == TrajectoryFormat::TUM && !TumStampsAreScanIndices(path);
}

// Pairs by time stamp (else by index) under options.association.
bool PairsByTime(const TrajectoryEvaluationOptions& options,
                 const EvaluationReference& reference,
                 const TrajectoryEvaluation& result,
                 bool* by_time,
                 std::string* error) {
  const bool estimate_timed = EstimateTimed(result.format, result.file);
  *by_time = false;
  switch (options.association) {
    case PoseAssociation::AUTO:
      *by_time = estimate_timed && reference.timed;
      break;
    case PoseAssociation::INDEX:
      break;
    case PoseAssociation::TIMESTAMP:
      if (!estimate_timed || !reference.timed) {
        *error = (estimate_timed ? reference.path : result.file) +
                 ": no time stamps (KITTI, or a TUM file whose header says "
                 "its stamps are scan indices): --association=timestamp "
                 "needs stamps on both sides";
        return false;
      }
      *by_time = true;
      break;
  }
  return true;
}

// The reference, converted with the calibration and stamped with the times.
bool ReadReference(const TrajectoryFiles& files,
                   EvaluationReference* reference,
                   std::string* error) {
  reference->path = files.reference;
  if (!ReadEvaluationTrajectory(files.reference,
                                files.detect_reference,
                                files.reference_format,
                                files.reference_calib,
                                &reference->trajectory,
                                &reference->format,
                                error)) {
    *error = "--reference: " + *error;
    return false;
  }
  if (!files.reference_times.empty()) {
    if (reference->format != TrajectoryFormat::KITTI) {
      *error =
          "--reference_times applies to a KITTI --reference (a TUM "
          "file has its own stamps)";
      return false;
    }
    if (!StampTrajectory(
            files.reference_times, &reference->trajectory, error)) {
      *error = "--reference_times=" + *error;
      return false;
    }
  }
  reference->timed = !files.reference_times.empty() ||
                     (reference->format == TrajectoryFormat::TUM &&
                      !TumStampsAreScanIndices(files.reference));
  return true;
}

}  // namespace

bool ReadTrajectoryFiles(const TrajectoryEvaluationOptions& options,
                         const TrajectoryFiles& files,
                         EvaluationReference* reference,
                         std::vector<Trajectory>* estimates,
                         std::vector<TrajectoryEvaluation>* results,
                         std::string* error) {
  if (!ReadReference(files, reference, error)) return false;
  const size_t n = files.estimates.size();
  results->assign(n, TrajectoryEvaluation());
  estimates->assign(n, Trajectory());
  for (size_t i = 0; i < n; ++i) {
    TrajectoryEvaluation& result = (*results)[i];
    result.file = files.estimates[i];
    if (!ReadEvaluationTrajectory(result.file,
                                  files.detect_estimate,
                                  files.estimate_format,
                                  "",
                                  &(*estimates)[i],
                                  &result.format,
                                  error) ||
        !CheckIndexPairing(options,
                           *reference,
                           result.file,
                           result.format,
                           (*estimates)[i],
                           error)) {
      return false;
    }
  }
  return true;
}

const char* PoseAssociationToString(PoseAssociation association) {
  // PoseAssociationTable's names in lower case (the flag's and the JSON's
  // spelling), made once.
  static const std::vector<std::pair<int, std::string>> names = [] {
    std::vector<std::pair<int, std::string>> lower;
    for (const EnumTable::Name& name : PoseAssociationTable().names()) {
      std::string text = name.name;
      for (char& c : text) c = static_cast<char>(std::tolower(c));
      lower.emplace_back(name.value, text);
    }
    return lower;
  }();
  for (const auto& [value, name] : names) {
    if (value == static_cast<int>(association)) return name.c_str();
  }
  return "unknown";
}

bool StringToPoseAssociation(const std::string& value,
                             PoseAssociation* association) {
  for (const EnumTable::Name& name : PoseAssociationTable().names()) {
    const auto a = static_cast<PoseAssociation>(name.value);
    if (value == PoseAssociationToString(a)) {
      *association = a;
      return true;
    }
  }
  return false;
}

bool ReadEvaluationTrajectory(const std::string& path,
                              bool detect,
                              TrajectoryFormat given,
                              const std::string& calib,
                              Trajectory* trajectory,
                              TrajectoryFormat* format,
                              std::string* error) {
  *format = given;
  if (detect && !DetectTrajectoryFormat(path, format, error)) return false;
  if (!ReadTrajectory(path, *format, trajectory, error)) return false;
  if (calib.empty()) return true;
  Isometry3d cam0_from_velo;
  if (!ReadKittiCalibTr(calib, &cam0_from_velo, error)) return false;
  Trajectory converted;
  for (size_t k = 0; k < trajectory->size(); ++k) {
    converted.Add(trajectory->timestamp_s(k),
                  cam0_from_velo.inverse() * trajectory->world_from_sensor(k) *
                      cam0_from_velo);
  }
  *trajectory = converted;
  return true;
}

bool StampTrajectory(const std::string& times_path,
                     Trajectory* trajectory,
                     std::string* error) {
  std::vector<double> stamps;
  if (!ReadScanTimes(times_path, &stamps, error)) return false;
  if (stamps.size() != trajectory->size()) {
    *error = times_path + " has " + std::to_string(stamps.size()) +
             " stamps for " + std::to_string(trajectory->size()) + " poses";
    return false;
  }
  Trajectory stamped;
  for (size_t k = 0; k < stamps.size(); ++k) {
    stamped.Add(stamps[k], trajectory->world_from_sensor(k));
  }
  *trajectory = stamped;
  return true;
}

bool CheckIndexPairing(const TrajectoryEvaluationOptions& options,
                       const EvaluationReference& reference,
                       const std::string& path,
                       TrajectoryFormat format,
                       const Trajectory& estimate,
                       std::string* error) {
  // As PairsByTime decides: AUTO pairs by time only when both are timed.
  const bool timed = EstimateTimed(format, path);
  const bool by_time = options.association == PoseAssociation::TIMESTAMP ||
                       (options.association == PoseAssociation::AUTO && timed &&
                        reference.timed);
  const size_t n = reference.trajectory.size();
  if (by_time || options.association != PoseAssociation::AUTO ||
      estimate.size() == n) {
    return true;
  }
  // One side timed, the other stamped with scan indices (or KITTI).
  const std::string mixed =
      timed == reference.timed
          ? ""
          : "; " + (timed ? path : reference.path) + " has time stamps, " +
                (timed ? reference.path : path) +
                " none (KITTI, or TUM stamped with scan indices), so they "
                "cannot pair by time";
  *error = path + " has " + std::to_string(estimate.size()) +
           " poses, --reference " + std::to_string(n) +
           ": poses are paired by index, so the lengths must match "
           "(--association=index evaluates the first " +
           std::to_string(std::min(estimate.size(), n)) +
           " explicitly; two files with time stamps pair by timestamp" + mixed +
           ")";
  return false;
}

bool TrajectoryEvaluationOptions::IsValid(std::string* error) const {
  return TrajectoryEvaluationOptionsTable().Check(*this, error);
}

bool EvaluateTrajectory(const TrajectoryEvaluationOptions& options,
                        const EvaluationReference& reference,
                        const Trajectory& estimate,
                        TrajectoryEvaluation* result,
                        std::string* error) {
  if (!options.IsValid(error)) return false;
  result->poses = estimate.size();
  bool by_time = false;
  if (!PairsByTime(options, reference, *result, &by_time, error)) return false;
  result->association = by_time ? "timestamp" : "index";
  const AssociatedPoses pairs =
      by_time
          ? AssociateByTimestamp(
                reference.trajectory, estimate, options.max_time_difference_s)
          : AssociateByIndex(reference.trajectory, estimate);
  result->pairs = pairs.size();
  if (pairs.size() == 0) {
    *error = result->file + ": no pose pairs with the reference (" +
             result->association + " association)";
    return false;
  }
  result->path_length_m = PathDistancesM(pairs.reference).back();
  AteOptions ate;
  ate.alignment = options.alignment;
  bool ok =
      ComputeAte(ate, pairs.reference, pairs.estimate, &result->ate, error);
  RpeOptions rpe;
  rpe.delta = options.delta;
  if (ok && pairs.size() > static_cast<size_t>(options.delta)) {
    ok = ComputeRpe(rpe, pairs.reference, pairs.estimate, &result->rpe, error);
    result->rpe_pairs = pairs.size() - static_cast<size_t>(options.delta);
  }
  ok = ok && ComputeKittiSegmentErrors(options.segments,
                                       pairs.reference,
                                       pairs.estimate,
                                       &result->kitti,
                                       error);
  if (!ok) *error = result->file + ": " + *error;
  return ok;
}

}  // namespace mlndt
