#include "lab/bench/bench_pairs.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>

#include "lab/eval/reference_pairs.h"
#include "mlndt/cloud/io.h"

namespace mlndt {
namespace {

// One folder with a reference_pairs.json, as a set named `set`.
struct Folder {
  std::string set;
  std::string dir;
  std::vector<int64_t> steps;  // Empty: all.
};

bool ParseStarts(const BenchPairsOptions& options,
                 SuitePlanOptions* plan,
                 std::string* error) {
  const std::vector<std::string>& items = options.starts;
  plan->starts.clear();
  if (items.empty()) {
    *error =
        "--starts: expected a comma-separated list of identity, prior, "
        "offsets";
    return false;
  }
  for (const std::string& item : items) {
    StartKind kind;
    if (!StringToStartKind(item, &kind) ||
        (kind != StartKind::IDENTITY && kind != StartKind::PRIOR &&
         kind != StartKind::OFFSETS)) {
      *error = "--starts: '" + item + "' is not identity, prior or offsets";
      return false;
    }
    plan->starts.push_back(kind);
  }
  const bool offsets =
      std::count(plan->starts.begin(), plan->starts.end(), StartKind::OFFSETS) >
      0;
  if (offsets && !ParseStartOffsets(options.offsets, &plan->offsets, error)) {
    *error = "--offsets: " + *error;
    return false;
  }
  if (options.max_pairs < 0) {
    *error = "--max_pairs must be >= 0";
    return false;
  }
  plan->max_pairs_per_set = static_cast<size_t>(options.max_pairs);
  return true;
}

// The bundled sets of --pairs under `dir`, in the fixed order koide3, kitti.
bool BundledFolders(const BenchPairsOptions& options,
                    std::vector<Folder>* folders,
                    std::string* error) {
  const std::vector<std::string>& listed = options.sets;
  if (listed.empty()) {
    *error = "--pairs: expected koide3, kitti or both";
    return false;
  }
  for (const std::string& set : listed) {
    if (set != "koide3" && set != "kitti") {
      *error = "--pairs: '" + set + "' is not koide3 or kitti";
      return false;
    }
  }
  const std::vector<int>& gaps = options.kitti_gaps;
  if (gaps.empty() ||
      std::any_of(gaps.begin(), gaps.end(), [](int g) { return g < 1; })) {
    *error = "--kitti_gaps: expected comma-separated integers >= 1";
    return false;
  }
  for (const char* set : {"koide3", "kitti"}) {
    if (std::find(listed.begin(), listed.end(), set) == listed.end()) continue;
    Folder folder{set, options.data_dir + "/" + set, {}};
    if (folder.set == "kitti") folder.steps.assign(gaps.begin(), gaps.end());
    folders->push_back(folder);
  }
  return true;
}

// Scans by number, each read once.
class SharedScans {
 public:
  explicit SharedScans(DatasetScanFiles files) : files_(std::move(files)) {}
  std::shared_ptr<const PointCloud> Get(int64_t number, std::string* error) {
    auto& scan = scans_[number];
    if (scan != nullptr) return scan;
    std::string path;
    auto cloud = std::make_shared<PointCloud>();
    if (!FindScanFile(files_, number, &path, error) ||
        !ReadPointCloud(path, cloud.get(), nullptr, error)) {
      return nullptr;
    }
    scan = cloud;
    return scan;
  }

 private:
  DatasetScanFiles files_;
  std::map<int64_t, std::shared_ptr<const PointCloud>> scans_;
};

std::string RunLabel(const SuiteRun& run) {
  char label[96];
  std::snprintf(label,
                sizeof(label),
                "%06lld<-%06lld",
                static_cast<long long>(run.reference_index),
                static_cast<long long>(run.input_index));
  return run.kind == StartKind::IDENTITY ? label
                                         : std::string(label) + " " + run.start;
}

bool LoadFolder(const Folder& folder,
                SuitePlanOptions plan,
                std::vector<ScanPair>* pairs,
                std::string* error) {
  std::map<std::string, ReferencePair> references;
  DatasetScanFiles files;
  if (!ReadReferencePairs(
          folder.dir + "/reference_pairs.json", &references, error) ||
      !ListDatasetScanFiles(folder.dir, &files, error)) {
    return false;
  }
  plan.steps = folder.steps;
  SuiteSkips skips;
  const std::vector<SuiteRun> runs =
      PlanDatasetRuns(plan, 0, folder.set, references, &skips);
  if (runs.empty()) {
    *error = folder.dir + ": no pair to run (steps, or no prior for --starts)";
    return false;
  }
  SharedScans scans(files);
  for (const SuiteRun& run : runs) {
    ScanPair pair;
    pair.set = run.kind == StartKind::IDENTITY
                   ? folder.set
                   : folder.set + "/" + StartKindToString(run.kind);
    pair.label = RunLabel(run);
    pair.reference = scans.Get(run.reference_index, error);
    pair.input = scans.Get(run.input_index, error);
    if (pair.reference == nullptr || pair.input == nullptr) {
      *error = folder.dir + ", pair " + run.pair_key + ": " + *error;
      return false;
    }
    pair.reference_from_input_truth = run.reference_from_input;
    pair.initial_reference_from_input = run.initial_reference_from_input;
    pairs->push_back(std::move(pair));
  }
  return true;
}

}  // namespace

bool IsDatasetFolder(const std::string& dir) {
  std::error_code ec;
  return std::filesystem::is_regular_file(dir + "/reference_pairs.json", ec);
}

std::vector<std::string> BenchSets(const std::vector<ScanPair>& pairs) {
  std::vector<std::string> sets;
  for (const ScanPair& pair : pairs) {
    if (std::find(sets.begin(), sets.end(), pair.set) == sets.end())
      sets.push_back(pair.set);
  }
  return sets;
}

bool LoadBenchPairs(const BenchPairsOptions& options,
                    std::vector<ScanPair>* pairs,
                    std::string* error) {
  SuitePlanOptions plan;
  if (!ParseStarts(options, &plan, error)) return false;
  std::vector<Folder> folders;
  if (IsDatasetFolder(options.data_dir)) {
    // The folder's name, also with a trailing '/'.
    std::filesystem::path dir =
        std::filesystem::path(options.data_dir).lexically_normal();
    if (dir.filename().empty()) dir = dir.parent_path();
    const std::string name = dir.filename();
    folders.push_back(
        {name.empty() ? options.data_dir : name, options.data_dir, {}});
  } else if (!BundledFolders(options, &folders, error)) {
    return false;
  }
  if (folders.empty()) {
    *error = "--pairs: no set given";
    return false;
  }
  for (const Folder& folder : folders) {
    if (!LoadFolder(folder, plan, pairs, error)) return false;
  }
  return true;
}

}  // namespace mlndt
