#include "tools/cli/localize_guesses.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "lab/eval/trajectory_io.h"
#include "tools/cli/map_inputs.h"

namespace mlndt {
namespace tools {

namespace {

// Reads `path` (TUM) and picks scan i's guess into (*guesses)[i]; false
// with *error naming the first scan without a guess, or the file's error.
bool ReadScanGuesses(const std::string& path,
                     const ScanInput& input,
                     double max_time_difference_s,
                     std::vector<Isometry3d>* guesses,
                     std::string* error) {
  Trajectory file;
  if (!ReadTrajectory(path, TrajectoryFormat::TUM, &file, error)) {
    *error = "--guesses: " + *error;
    return false;
  }
  const std::vector<double>& stamps = file.timestamps_s();
  guesses->clear();
  for (size_t i = 0; i < input.names().size(); ++i) {
    const double stamp = input.StampOf(i);
    // The nearest stamp (the file's stamps increase strictly).
    const auto after = std::lower_bound(stamps.begin(), stamps.end(), stamp);
    size_t nearest = static_cast<size_t>(after - stamps.begin());
    if (nearest == stamps.size() ||
        (nearest > 0 &&
         stamp - stamps[nearest - 1] < stamps[nearest] - stamp)) {
      if (nearest > 0) --nearest;
    }
    if (stamps.empty() ||
        std::abs(stamps[nearest] - stamp) > max_time_difference_s) {
      char message[300];
      std::snprintf(message,
                    sizeof(message),
                    "--guesses=%s holds no pose within %g s of scan %zu's "
                    "stamp %.6f (%s); give one guess per scan",
                    path.c_str(),
                    max_time_difference_s,
                    i,
                    stamp,
                    input.has_stamps() ? "its time stamp"
                                       : "its index: the scans have no times");
      *error = message;
      return false;
    }
    guesses->push_back(file.poses()[nearest]);
  }
  return true;
}

}  // namespace

bool CheckGuessesFlag(const std::string& path,
                      const std::string& other_initial,
                      double max_time_difference_s,
                      std::string* error) {
  if (!(max_time_difference_s >= 0.0)) {
    *error = "--guesses_max_time_difference_s must be >= 0";
    return false;
  }
  if (!path.empty() && !other_initial.empty()) {
    *error =
        "--guesses gives every scan's guess: it does not go with "
        "--initial_guess, --initial_matrix or --initial_poses";
    return false;
  }
  return true;
}

bool InitialGuessesFromFlags(const InitialPoseFlags& flags,
                             const std::string& guesses_path,
                             double max_time_difference_s,
                             const ScanInput& input,
                             Isometry3d* first_guess,
                             std::vector<Isometry3d>* guesses,
                             std::string* error) {
  guesses->clear();
  if (!InitialPoseFromFlags(flags.guess,
                            flags.matrix,
                            flags.poses,
                            flags.poses_format,
                            flags.calib,
                            first_guess,
                            error)) {
    return false;
  }
  if (guesses_path.empty()) return true;
  if (!ReadScanGuesses(
          guesses_path, input, max_time_difference_s, guesses, error)) {
    return false;
  }
  if (!guesses->empty()) *first_guess = guesses->front();
  return true;
}

}  // namespace tools
}  // namespace mlndt
