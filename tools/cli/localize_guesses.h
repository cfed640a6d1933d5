#pragma once

// mlndt_localize --guesses=FILE: one initial guess (map_from_scan) per scan
// from a TUM file (odometry, a pose file), matched to the scans by time
// stamp. The scans' stamps are the bag's or the --times file's; without
// them a scan's stamp is its index (0, 1, 2, ...), as the tool's own TUM
// output writes them. Every scan needs the guess whose stamp is nearest its
// own and within max_time_difference_s; a scan without one, or a file that
// is not TUM, is refused before any work (exit 2, nothing written).

#include <string>
#include <vector>

#include "mlndt/common/types.h"
#include "tools/cli/scan_input.h"

namespace mlndt {
namespace tools {

// --guesses: not with another initial pose flag (`other_initial`, the
// others concatenated), a time difference >= 0; false with *error.
bool CheckGuessesFlag(const std::string& path,
                      const std::string& other_initial,
                      double max_time_difference_s,
                      std::string* error);

// The first-pose flags of InitialPoseFromFlags (map_inputs.h), in order.
struct InitialPoseFlags {
  std::string guess;
  std::string matrix;
  std::string poses;
  std::string poses_format;
  std::string calib;
};

// The first scan's guess from the first-pose flags, or with --guesses
// (`guesses_path` not empty) every scan's (ReadScanGuesses) and the first
// of them; false with *error.
bool InitialGuessesFromFlags(const InitialPoseFlags& flags,
                             const std::string& guesses_path,
                             double max_time_difference_s,
                             const ScanInput& input,
                             Isometry3d* first_guess,
                             std::vector<Isometry3d>* guesses,
                             std::string* error);

}  // namespace tools
}  // namespace mlndt
