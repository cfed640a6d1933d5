#include "lab/experiments/datasets.h"

#include <algorithm>
#include <filesystem>

namespace mlndt {
namespace experiments {
namespace {

struct KnownDataset {
  std::string name;
  std::vector<std::string> folders;  // Tried in order.
  SuccessCriterion criterion;
};

// The tolerances of mlndt_suite's documented shared run (3DTK and the room
// pair are indoor scans with references good to ~1 cm / 5 cm).
const std::vector<KnownDataset>& KnownDatasets() {
  static const auto* const kKnown = new std::vector<KnownDataset>{
      {"kitti", {"kitti00_frames_0000_0007", "kitti"}, {0.2, 1.0}},
      {"mulran", {"mulran_kaist03_keyframes", "mulran"}, {0.2, 1.0}},
      {"3dtk", {"3dtk_example_scans", "3dtk"}, {0.1, 1.0}},
      {"room", {"pcl_room_scans", "room"}, {0.1, 1.0}},
      {"koide3", {"koide3_velodyne_pair", "koide3"}, {0.2, 1.0}},
  };
  return *kKnown;
}

int64_t Step(const ReferencePair& pair) {
  return pair.input_index - pair.reference_index;
}

}  // namespace

std::vector<std::string> ExperimentDataset::PairsWithStep(int64_t step) const {
  std::vector<std::string> keys;
  for (const std::string& key : PairsByStep()) {
    if (Step(pairs.at(key)) == step) keys.push_back(key);
  }
  return keys;
}

std::vector<std::string> ExperimentDataset::PairsByStep() const {
  std::vector<std::string> keys;
  for (const auto& [key, pair] : pairs) keys.push_back(key);
  std::sort(keys.begin(), keys.end(), [&](const auto& a, const auto& b) {
    const ReferencePair& pa = pairs.at(a);
    const ReferencePair& pb = pairs.at(b);
    return std::make_pair(Step(pa), pa.reference_index) <
           std::make_pair(Step(pb), pb.reference_index);
  });
  return keys;
}

bool FindDatasets(const std::string& data_dir,
                  std::vector<ExperimentDataset>* datasets,
                  std::vector<std::string>* missing,
                  std::string* error) {
  namespace fs = std::filesystem;
  datasets->clear();
  missing->clear();
  for (const KnownDataset& known : KnownDatasets()) {
    std::string dir;
    for (const std::string& folder : known.folders) {
      if (fs::exists(data_dir + "/" + folder + "/reference_pairs.json")) {
        dir = data_dir + "/" + folder;
        break;
      }
    }
    if (dir.empty()) {
      missing->push_back(known.name);
      continue;
    }
    ExperimentDataset set;
    set.name = known.name;
    set.dir = dir;
    set.criterion = known.criterion;
    DatasetScanFiles files;
    if (!ReadReferencePairs(dir + "/reference_pairs.json", &set.pairs, error) ||
        !ListDatasetScanFiles(dir, &files, error)) {
      return false;
    }
    for (const auto& [key, pair] : set.pairs) {
      for (const int64_t number : {pair.reference_index, pair.input_index}) {
        std::string path;
        if (set.scan_paths.count(number)) continue;
        if (!FindScanFile(files, number, &path, error)) {
          *error = dir + ": " + *error;
          return false;
        }
        set.scan_paths[number] = path;
      }
    }
    datasets->push_back(std::move(set));
  }
  return true;
}

}  // namespace experiments
}  // namespace mlndt
