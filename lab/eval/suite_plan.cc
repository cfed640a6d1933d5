#include "lab/eval/suite_plan.h"

#include <glog/logging.h>

#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <random>
#include <sstream>
#include <system_error>
#include <tuple>

#include "lab/eval/dataset.h"
#include "lab/eval/suite_plan_option_table.h"
#include "mlndt/common/internal/enum_strings.h"
#include "mlndt/common/pose.h"

namespace mlndt {
namespace {

namespace fs = std::filesystem;

// The files of `paths` whose number is `number`.
std::vector<std::string> FilesNumbered(const std::vector<std::string>& paths,
                                       int64_t number) {
  std::vector<std::string> found;
  for (const std::string& path : paths) {
    int64_t n = 0;
    if (ScanNumberFromFileName(path, &n) && n == number) found.push_back(path);
  }
  return found;
}

// The axes of an offset family, in pose-vector order (0-2 translation,
// 3-5 rotation). False for an unknown or repeated axis.
bool ParseAxes(const std::string& text, std::vector<int>* axes) {
  static const std::vector<std::pair<std::string, int>> kNames = {
      {"pitch", 4}, {"roll", 3}, {"yaw", 5}, {"x", 0}, {"y", 1}, {"z", 2}};
  axes->clear();
  size_t at = 0;
  while (at < text.size()) {
    if (text[at] == '+') {
      ++at;
      continue;
    }
    bool matched = false;
    for (const auto& [name, axis] : kNames) {
      if (text.compare(at, name.size(), name) != 0) continue;
      if (std::find(axes->begin(), axes->end(), axis) != axes->end()) {
        return false;
      }
      axes->push_back(axis);
      at += name.size();
      matched = true;
      break;
    }
    if (!matched) return false;
  }
  return !axes->empty();
}

bool ParseNumbers(const std::string& text, std::vector<double>* values) {
  values->clear();
  std::stringstream list(text);
  std::string item;
  while (std::getline(list, item, ',')) {
    size_t used = 0;
    double v = 0.0;
    try {
      v = std::stod(item, &used);
    } catch (...) {
      return false;
    }
    while (used < item.size() && item[used] == ' ') ++used;
    if (used != item.size() || !std::isfinite(v)) return false;
    values->push_back(v);
  }
  return !values->empty() && text.back() != ',';
}

std::string Trim(const std::string& text) {
  const size_t first = text.find_first_not_of(" \t");
  if (first == std::string::npos) return "";
  return text.substr(first, text.find_last_not_of(" \t") - first + 1);
}

// Parses one "AXES:values" family, appending its offsets.
bool ParseFamily(const std::string& item,
                 std::vector<StartOffset>* offsets,
                 std::string* error) {
  const size_t colon = item.find(':');
  std::vector<int> axes;
  std::vector<double> values;
  const std::string family = Trim(item.substr(0, colon));
  if (colon == std::string::npos || !ParseAxes(family, &axes)) {
    *error = "'" + item +
             "': expected AXES:values with AXES of x, y, z, roll, pitch, "
             "yaw (each once)";
    return false;
  }
  if (!ParseNumbers(item.substr(colon + 1), &values) ||
      values.size() % axes.size() != 0) {
    *error = "'" + item + "': expected a comma-separated list of " +
             (axes.size() == 1
                  ? std::string("numbers")
                  : "groups of " + std::to_string(axes.size()) + " numbers");
    return false;
  }
  for (size_t first = 0; first < values.size(); first += axes.size()) {
    StartOffset offset;
    offset.family = family;
    std::ostringstream label;
    label << family << "=";
    for (size_t k = 0; k < axes.size(); ++k) {
      const double v = values[first + k];
      label << (k > 0 ? "," : "") << v;
      offset.reference_xi(axes[k]) = axes[k] >= 3 ? v * kDegToRad : v;
    }
    offset.label = label.str();
    offsets->push_back(offset);
  }
  return true;
}

// FNV-1a of `text`, mixed with `seed` by splitmix64: a seed that does not
// depend on the standard library.
uint64_t MixSeed(uint64_t seed, const std::string& text) {
  uint64_t h = 1469598103934665603ULL;
  for (const char c : text) {
    h ^= static_cast<unsigned char>(c);
    h *= 1099511628211ULL;
  }
  uint64_t z = h ^ (seed + 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

Vector3d RandomUnitVector(std::mt19937_64* rng) {
  std::normal_distribution<double> normal(0.0, 1.0);
  for (;;) {
    const Vector3d v(normal(*rng), normal(*rng), normal(*rng));
    if (v.norm() > 1e-9) return v.normalized();
  }
}

// `transform` with its rotation replaced by the nearest rotation (SVD):
// the files print 6-9 significant digits, too few for the registration's
// rigidity check of the initial guess.
Isometry3d NearestRigid(const Isometry3d& transform) {
  const Eigen::JacobiSVD<Matrix3d> svd(
      transform.linear(), Eigen::ComputeFullU | Eigen::ComputeFullV);
  Matrix3d u = svd.matrixU();
  if ((u * svd.matrixV().transpose()).determinant() < 0.0) u.col(2) *= -1.0;
  Isometry3d rigid = Isometry3d::Identity();
  rigid.linear() = u * svd.matrixV().transpose();
  rigid.translation() = transform.translation();
  return rigid;
}

// Pairs kept by the steps filter and the cap, sorted by (reference, input).
std::vector<const ReferencePair*> SelectPairs(
    const SuitePlanOptions& options,
    const std::map<std::string, ReferencePair>& pairs) {
  std::vector<const ReferencePair*> kept;
  for (const auto& [key, pair] : pairs) {
    const int64_t step = pair.input_index - pair.reference_index;
    if (pairs.size() > 1 && !options.steps.empty() &&
        std::find(options.steps.begin(), options.steps.end(), step) ==
            options.steps.end()) {
      continue;
    }
    kept.push_back(&pair);
  }
  const auto by = [](const ReferencePair* p) {
    return std::make_tuple(p->input_index - p->reference_index,
                           p->reference_index);
  };
  if (options.max_pairs_per_set > 0 &&
      kept.size() > options.max_pairs_per_set) {
    std::stable_sort(kept.begin(), kept.end(), [&](auto* a, auto* b) {
      return by(a) < by(b);
    });
    kept.resize(options.max_pairs_per_set);
  }
  std::sort(kept.begin(), kept.end(), [](auto* a, auto* b) {
    return std::make_pair(a->reference_index, a->input_index) <
           std::make_pair(b->reference_index, b->input_index);
  });
  return kept;
}

// Appends the runs of start kind base.kind for `pair` (base filled with
// the pair and the kind); false when the kind does not apply to the pair.
bool AppendStartRuns(const SuitePlanOptions& options,
                     const std::string& dataset_name,
                     const std::map<std::string, ReferencePair>& pairs,
                     const ReferencePair& pair,
                     const SuiteRun& base,
                     std::vector<SuiteRun>* runs) {
  SuiteRun run = base;
  const Isometry3d& reference = pair.reference_from_input;
  switch (base.kind) {
    case StartKind::IDENTITY:
      runs->push_back(run);
      return true;
    case StartKind::PRIOR:
      if (!pair.prior_from_input) return false;
      run.initial_reference_from_input = *pair.prior_from_input;
      run.uncertainty = options.prior_uncertainty;
      runs->push_back(run);
      return true;
    case StartKind::OFFSETS:
      for (size_t k = 0; k < options.offsets.size(); ++k) {
        run.start = options.offsets[k].label;
        run.offset_index = static_cast<int>(k);
        // Offset ∘ reference: pushed off in the reference frame.
        run.initial_reference_from_input =
            PoseVectorToIsometry(options.offsets[k].reference_xi) * reference;
        runs->push_back(run);
      }
      return true;
    case StartKind::PERTURBED:
      for (int k = 0; k < options.perturb_count; ++k) {
        run.start = "perturbed#" + std::to_string(k);
        run.initial_reference_from_input =
            RandomStartOffset(
                options.perturb_translation_m,
                options.perturb_rotation_deg,
                options.perturb_seed,
                dataset_name + "/" + base.pair_key + "/" + std::to_string(k)) *
            reference;
        run.uncertainty = {
            true, options.perturb_translation_m, options.perturb_rotation_deg};
        runs->push_back(run);
      }
      return true;
    case StartKind::CONSTANT_VELOCITY: {
      const int64_t step = pair.input_index - pair.reference_index;
      const int64_t first = pair.reference_index - step;
      if (step <= 0 || first < 0) return false;
      const auto previous =
          pairs.find(ReferencePairKey(first, pair.reference_index));
      if (previous == pairs.end()) return false;
      run.initial_reference_from_input = previous->second.reference_from_input;
      runs->push_back(run);
      return true;
    }
  }
  return false;
}

}  // namespace

bool ScanNumberFromFileName(const std::string& path, int64_t* number) {
  CHECK(number != nullptr);
  const std::string stem = fs::path(path).stem().string();
  std::string digits;
  for (const char c : stem) {
    if (c >= '0' && c <= '9') digits += c;
  }
  if (digits.empty() || digits.size() > 18) return false;
  *number = std::stoll(digits);
  return true;
}

bool ListDatasetScanFiles(const std::string& dir,
                          DatasetScanFiles* files,
                          std::string* error) {
  CHECK(files != nullptr);
  CHECK(error != nullptr);
  *files = DatasetScanFiles();
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) {
    *error = dir + ": not a folder";
    return false;
  }
  std::string ignored;
  const std::string pcd = (fs::path(dir) / "pcd").string();
  if (fs::is_directory(pcd, ec)) {
    ListScanFiles(pcd, {}, &files->pcd_folder, &ignored);
  }
  ListScanFiles(dir, {}, &files->folder, &ignored);
  if (files->pcd_folder.empty() && files->folder.empty()) {
    *error = dir + ": no point-cloud files in it or in pcd/";
    return false;
  }
  return true;
}

bool FindScanFile(const DatasetScanFiles& files,
                  int64_t number,
                  std::string* path,
                  std::string* error) {
  CHECK(path != nullptr);
  CHECK(error != nullptr);
  for (const auto* folder : {&files.pcd_folder, &files.folder}) {
    const std::vector<std::string> found = FilesNumbered(*folder, number);
    if (found.size() == 1) {
      *path = found.front();
      return true;
    }
    if (found.size() > 1) {
      *error = "scan " + std::to_string(number) + " is ambiguous: ";
      for (size_t k = 0; k < found.size(); ++k) {
        *error += (k > 0 ? ", " : "") + found[k];
      }
      return false;
    }
  }
  *error = "no scan file numbered " + std::to_string(number) +
           " (the digits of the file name)";
  return false;
}

const char* StartKindToString(StartKind kind) {
  switch (kind) {
    case StartKind::IDENTITY:
      return "identity";
    case StartKind::PRIOR:
      return "prior";
    case StartKind::OFFSETS:
      return "offsets";
    case StartKind::PERTURBED:
      return "perturbed";
    case StartKind::CONSTANT_VELOCITY:
      return "constant_velocity";
  }
  return "unknown";
}

bool StringToStartKind(std::string value, StartKind* result) {
  UpperCase(&value);
  MLNDT_STRING_TO_ENUM(IDENTITY, StartKind);
  MLNDT_STRING_TO_ENUM(PRIOR, StartKind);
  MLNDT_STRING_TO_ENUM(OFFSETS, StartKind);
  MLNDT_STRING_TO_ENUM(PERTURBED, StartKind);
  MLNDT_STRING_TO_ENUM(CONSTANT_VELOCITY, StartKind);
  return false;
}

bool ParseStartOffsets(const std::string& text,
                       std::vector<StartOffset>* offsets,
                       std::string* error) {
  CHECK(offsets != nullptr);
  CHECK(error != nullptr);
  offsets->clear();
  std::stringstream list(text);
  std::string item;
  while (std::getline(list, item, ';')) {
    if (!ParseFamily(item, offsets, error)) return false;
  }
  if (offsets->empty() || text.back() == ';') {
    *error = "'" + text + "': expected AXES:values[;AXES:values...]";
    return false;
  }
  return true;
}

Isometry3d RandomStartOffset(double max_translation_m,
                             double max_rotation_deg,
                             uint64_t seed,
                             const std::string& text) {
  std::mt19937_64 rng(MixSeed(seed, text));
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const Vector3d direction = RandomUnitVector(&rng);
  const double length = max_translation_m * unit(rng);
  const Vector3d axis = RandomUnitVector(&rng);
  const double angle = max_rotation_deg * kDegToRad * unit(rng);
  Isometry3d offset = Isometry3d::Identity();
  offset.linear() = Eigen::AngleAxisd(angle, axis).toRotationMatrix();
  offset.translation() = length * direction;
  return offset;
}

bool SuitePlanOptions::IsValid(std::string* error) const {
  CHECK(error != nullptr);
  if (starts.empty()) {
    *error = "no start kind";
    return false;
  }
  for (const StartKind kind : starts) {
    if (std::count(starts.begin(), starts.end(), kind) > 1) {
      *error =
          std::string("start kind ") + StartKindToString(kind) + " given twice";
      return false;
    }
  }
  if (std::count(starts.begin(), starts.end(), StartKind::OFFSETS) > 0 &&
      offsets.empty()) {
    *error = "start kind offsets without offsets";
    return false;
  }
  if (!SuitePlanOptionsTable().Check(*this, error)) return false;
  if (prior_uncertainty.given && (!(prior_uncertainty.translation_m >= 0.0 &&
                                    prior_uncertainty.translation_m <= 1e4) ||
                                  !(prior_uncertainty.rotation_deg >= 0.0 &&
                                    prior_uncertainty.rotation_deg <= 180.0))) {
    *error = "prior uncertainty must be in [0, 1e4] m and [0, 180] deg";
    return false;
  }
  for (const int64_t step : steps) {
    if (step == 0) {
      *error = "a step of 0";
      return false;
    }
  }
  return true;
}

std::vector<SuiteRun> PlanDatasetRuns(
    const SuitePlanOptions& options,
    size_t dataset,
    const std::string& dataset_name,
    const std::map<std::string, ReferencePair>& pairs,
    SuiteSkips* skips) {
  CHECK(skips != nullptr);
  std::vector<SuiteRun> runs;
  for (const ReferencePair* pair : SelectPairs(options, pairs)) {
    SuiteRun base;
    base.dataset = dataset;
    base.reference_index = pair->reference_index;
    base.input_index = pair->input_index;
    base.pair_key = ReferencePairKey(pair->reference_index, pair->input_index);
    base.reference_from_input = pair->reference_from_input;
    base.free_directions = pair->free_directions;
    for (const StartKind kind : options.starts) {
      base.kind = kind;
      base.start = StartKindToString(kind);
      const size_t first = runs.size();
      if (!AppendStartRuns(options, dataset_name, pairs, *pair, base, &runs)) {
        ++(*skips)[kind];
      }
      for (size_t k = first; k < runs.size(); ++k) {
        runs[k].initial_reference_from_input =
            NearestRigid(runs[k].initial_reference_from_input);
      }
    }
  }
  return runs;
}

}  // namespace mlndt
