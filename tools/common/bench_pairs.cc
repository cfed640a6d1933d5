#include "tools/common/bench_pairs.h"

#include <algorithm>
#include <cstdio>

#include "mlndt/cloud/io.h"
#include "mlndt/cloud/pose_io.h"
#include "tools/common/list_flags.h"
#include "tools/common/matrix_text.h"

namespace mlndt {
namespace tools {
namespace {

bool LoadKoide3(const std::string& dir,
                std::vector<ScanPair>* pairs,
                std::string* error) {
  ScanPair pair;
  pair.set = "koide3";
  pair.label = "251370668<-251371071";
  if (!ReadPointCloud(
          dir + "/koide3/251370668.pcd", &pair.reference, nullptr, error) ||
      !ReadPointCloud(
          dir + "/koide3/251371071.pcd", &pair.input, nullptr, error) ||
      !ReadMatrixFile(dir + "/koide3/T_target_source.txt",
                      &pair.reference_from_input_truth,
                      error)) {
    return false;
  }
  pairs->push_back(std::move(pair));
  return true;
}

// kitti/pcd/<j>.pcd onto <i>.pcd for j = i + gap, every gap in --kitti_gaps.
bool LoadKitti(const std::string& dir,
               const std::string& kitti_gaps,
               std::vector<ScanPair>* pairs,
               std::string* error) {
  std::vector<int> gaps;
  if (!ParseIntList(kitti_gaps, &gaps) ||
      std::any_of(gaps.begin(), gaps.end(), [](int g) { return g < 1; })) {
    *error = "--kitti_gaps: expected comma-separated integers >= 1";
    return false;
  }
  std::vector<Isometry3d> poses;
  if (!ReadKittiPoses(dir + "/kitti/poses_velo.txt", &poses, error))
    return false;
  std::vector<PointCloud> scans(poses.size());
  std::vector<std::string> names(poses.size());
  for (size_t i = 0; i < poses.size(); ++i) {
    char name[32];
    std::snprintf(name, sizeof(name), "%06zu", i);
    names[i] = name;
    if (!ReadPointCloud(
            dir + "/kitti/pcd/" + names[i] + ".pcd", &scans[i], nullptr, error))
      return false;
  }
  const size_t before = pairs->size();
  for (const int gap : gaps) {
    for (size_t i = 0; i + static_cast<size_t>(gap) < scans.size(); ++i) {
      const size_t j = i + static_cast<size_t>(gap);
      ScanPair pair;
      pair.set = "kitti";
      pair.label = names[i] + "<-" + names[j];
      pair.reference = scans[i];
      pair.input = scans[j];
      pair.reference_from_input_truth = poses[i].inverse() * poses[j];
      pairs->push_back(std::move(pair));
    }
  }
  if (pairs->size() == before) {
    *error = "--kitti_gaps: no pair of the " + std::to_string(scans.size()) +
             " KITTI scans is that far apart";
    return false;
  }
  return true;
}

}  // namespace

bool ParseBenchSets(const std::string& text,
                    std::vector<std::string>* sets,
                    std::string* error) {
  std::vector<std::string> listed;
  if (!SplitList(text, &listed)) {
    *error = "--pairs: expected koide3, kitti or both";
    return false;
  }
  for (const std::string& set : listed) {
    if (set != "koide3" && set != "kitti") {
      *error = "--pairs: '" + set + "' is not koide3 or kitti";
      return false;
    }
  }
  for (const char* set : {"koide3", "kitti"}) {
    if (std::find(listed.begin(), listed.end(), set) != listed.end())
      sets->push_back(set);
  }
  return true;
}

bool LoadBenchPairs(const std::string& dir,
                    const std::vector<std::string>& sets,
                    const std::string& kitti_gaps,
                    std::vector<ScanPair>* pairs,
                    std::string* error) {
  for (const std::string& set : sets) {
    const bool ok = set == "koide3" ? LoadKoide3(dir, pairs, error)
                                    : LoadKitti(dir, kitti_gaps, pairs, error);
    if (!ok) return false;
  }
  return true;
}

}  // namespace tools
}  // namespace mlndt
