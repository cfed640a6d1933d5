#include "tools/common/bench_pairs.h"

#include <algorithm>
#include <cstdio>
#include <map>

#include "lab/eval/reference_pairs.h"
#include "mlndt/cloud/io.h"
#include "tools/common/list_flags.h"

namespace mlndt {
namespace tools {
namespace {

bool ReadReferences(const std::string& folder,
                    std::map<std::string, ReferencePair>* references,
                    std::string* error) {
  return ReadReferencePairs(
      folder + "/reference_pairs.json", references, error);
}

bool LoadKoide3(const std::string& dir,
                std::vector<ScanPair>* pairs,
                std::string* error) {
  const std::string folder = dir + "/koide3";
  std::map<std::string, ReferencePair> references;
  if (!ReadReferences(folder, &references, error)) return false;
  const auto reference = references.find("251370668_251371071");
  if (reference == references.end()) {
    *error = folder + "/reference_pairs.json: no entry 251370668_251371071";
    return false;
  }
  ScanPair pair;
  pair.set = "koide3";
  pair.label = "251370668<-251371071";
  pair.reference_from_input_truth = reference->second.reference_from_input;
  if (!ReadPointCloud(
          folder + "/251370668.pcd", &pair.reference, nullptr, error) ||
      !ReadPointCloud(folder + "/251371071.pcd", &pair.input, nullptr, error)) {
    return false;
  }
  pairs->push_back(std::move(pair));
  return true;
}

// kitti/pcd/<j>.pcd onto <i>.pcd for j = i + gap, every gap in --kitti_gaps,
// for the pairs that reference_pairs.json has.
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
  const std::string folder = dir + "/kitti";
  std::map<std::string, ReferencePair> references;
  if (!ReadReferences(folder, &references, error)) return false;
  std::map<int64_t, PointCloud> scans;
  const auto scan = [&](int64_t index, PointCloud** cloud) {
    auto [it, inserted] = scans.try_emplace(index);
    *cloud = &it->second;
    if (!inserted) return true;
    char name[32];
    std::snprintf(name, sizeof(name), "%06lld", static_cast<long long>(index));
    return ReadPointCloud(
        folder + "/pcd/" + name + ".pcd", &it->second, nullptr, error);
  };
  const size_t before = pairs->size();
  for (const int gap : gaps) {
    for (const auto& [key, reference] : references) {
      if (reference.input_index - reference.reference_index != gap) continue;
      PointCloud *reference_scan = nullptr, *input_scan = nullptr;
      if (!scan(reference.reference_index, &reference_scan) ||
          !scan(reference.input_index, &input_scan)) {
        return false;
      }
      char label[64];
      std::snprintf(label,
                    sizeof(label),
                    "%06lld<-%06lld",
                    static_cast<long long>(reference.reference_index),
                    static_cast<long long>(reference.input_index));
      ScanPair pair;
      pair.set = "kitti";
      pair.label = label;
      pair.reference = *reference_scan;
      pair.input = *input_scan;
      pair.reference_from_input_truth = reference.reference_from_input;
      pairs->push_back(std::move(pair));
    }
  }
  if (pairs->size() == before) {
    *error = "--kitti_gaps: " + folder +
             "/reference_pairs.json has no pair that far apart";
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
