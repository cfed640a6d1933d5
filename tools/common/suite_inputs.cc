#include "tools/common/suite_inputs.h"

#include <filesystem>

#include "tools/common/list_flags.h"

namespace mlndt {
namespace tools {
namespace {

namespace fs = std::filesystem;

bool ParseDataset(const std::string& item,
                  const std::string& data_dir,
                  SuiteDataset* dataset,
                  std::string* error) {
  std::string dir = item;
  const size_t colon = item.find(':');
  if (colon != std::string::npos) {
    dir = item.substr(0, colon);
    std::vector<double> tolerances;
    const std::string rest = item.substr(colon + 1);
    std::string numbers = rest;
    for (char& c : numbers) c = c == ':' ? ',' : c;
    if (!ParseNumberList(numbers, &tolerances) || tolerances.size() != 2 ||
        !(tolerances[0] > 0.0) || !(tolerances[1] > 0.0)) {
      *error = "--datasets item '" + item +
               "': expected DIR or DIR:tol_m:tol_deg with tolerances > 0";
      return false;
    }
    dataset->criterion.max_translation_m = tolerances[0];
    dataset->criterion.max_rotation_deg = tolerances[1];
  }
  while (dir.size() > 1 && dir.back() == '/') dir.pop_back();
  if (dir.empty()) {
    *error = "--datasets item '" + item + "': no folder";
    return false;
  }
  dataset->name = fs::path(dir).filename().string();
  dataset->dir = data_dir.empty() || fs::path(dir).is_absolute()
                     ? dir
                     : (fs::path(data_dir) / dir).string();
  return true;
}

}  // namespace

bool ParseSuiteDatasets(const std::string& text,
                        const std::string& data_dir,
                        std::vector<SuiteDataset>* datasets,
                        std::string* error) {
  datasets->clear();
  std::vector<std::string> items;
  if (!SplitList(text, &items)) {
    *error = "--datasets='" + text +
             "': expected DIR[:tol_m:tol_deg],... (no empty item)";
    return false;
  }
  for (const std::string& item : items) {
    SuiteDataset dataset;
    if (!ParseDataset(item, data_dir, &dataset, error)) return false;
    for (const SuiteDataset& other : *datasets) {
      if (other.name == dataset.name) {
        *error = "--datasets: two data sets named '" + dataset.name +
                 "' (the folders' names must differ)";
        return false;
      }
    }
    datasets->push_back(dataset);
  }
  return true;
}

bool LoadSuiteDataset(const SuiteDataset& dataset,
                      size_t index,
                      const SuitePlanOptions& plan,
                      LoadedSuiteDataset* loaded,
                      std::string* error) {
  *loaded = LoadedSuiteDataset();
  loaded->dataset = dataset;
  const std::string prefix = "--datasets '" + dataset.name + "': ";
  std::error_code ec;
  if (!fs::is_directory(dataset.dir, ec)) {
    *error = prefix + dataset.dir + ": not a folder";
    return false;
  }
  const std::string pairs_path =
      (fs::path(dataset.dir) / "reference_pairs.json").string();
  if (!ReadReferencePairs(pairs_path, &loaded->pairs, error)) {
    *error = prefix + *error;
    return false;
  }
  DatasetScanFiles files;
  if (!ListDatasetScanFiles(dataset.dir, &files, error)) {
    *error = prefix + *error;
    return false;
  }
  loaded->runs =
      PlanDatasetRuns(plan, index, dataset.name, loaded->pairs, &loaded->skips);
  for (const SuiteRun& run : loaded->runs) {
    for (const int64_t number : {run.reference_index, run.input_index}) {
      if (loaded->scan_paths.count(number) > 0) continue;
      std::string path;
      if (!FindScanFile(files, number, &path, error)) {
        *error =
            prefix + dataset.dir + ": pair " + run.pair_key + ": " + *error;
        return false;
      }
      loaded->scan_paths[number] = path;
    }
  }
  return true;
}

}  // namespace tools
}  // namespace mlndt
