#include "lab/eval/suite_score.h"

#include <glog/logging.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <sstream>

#include "lab/eval/statistics.h"
#include "mlndt/common/internal/enum_strings.h"

namespace mlndt {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

double Ratio(size_t numerator, size_t denominator) {
  return denominator == 0 ? kNaN
                          : static_cast<double>(numerator) /
                                static_cast<double>(denominator);
}

size_t TypeIndex(const ConfusionTable& table, TerminationType type) {
  const auto it = std::find(table.types.begin(), table.types.end(), type);
  CHECK(it != table.types.end()) << TerminationTypeToString(type);
  return static_cast<size_t>(it - table.types.begin());
}

SuiteAccuracyRow Accuracy(size_t dataset,
                          StartKind kind,
                          const std::vector<SuiteOutcome>& outcomes) {
  SuiteAccuracyRow row;
  row.dataset = dataset;
  row.kind = kind;
  std::vector<double> translations, along, rotations, times;
  for (const SuiteOutcome& o : outcomes) {
    if (o.dataset != dataset || o.kind != kind || !o.right || o.free) {
      continue;
    }
    translations.push_back(o.error.translation_m);
    rotations.push_back(o.error.rotation_deg());
    times.push_back(o.time_ms);
    if (std::isfinite(o.along_track_m)) along.push_back(o.along_track_m);
  }
  row.right = translations.size();
  row.rms_translation_m = Rms(translations);
  row.rms_rotation_deg = Rms(rotations);
  row.mean_along_track_m = along.empty() ? kNaN : ComputeStats(along).mean;
  row.median_time_ms = ComputeStats(times).median;
  return row;
}

// The reach of the offsets `members` (indices, in order) given their
// shares: the last index before the first share below `minimum`.
int Reach(const std::vector<int>& members,
          const std::vector<SuiteShare>& shares,
          double minimum) {
  int reach = -1;
  bool any = false;
  for (const int k : members) {
    const SuiteShare& share = shares[static_cast<size_t>(k)];
    if (share.runs == 0) continue;
    any = true;
    if (share.share() < minimum) break;
    reach = k;
  }
  return any ? reach : -2;
}

void ScoreReach(const std::vector<SuiteOutcome>& outcomes, SuiteScore* score) {
  const size_t num_datasets = score->datasets.size();
  for (size_t k = 0; k < score->offsets.size(); ++k) {
    SuiteReachRow row;
    row.offset_index = static_cast<int>(k);
    row.per_dataset.resize(num_datasets);
    score->reach.push_back(row);
  }
  for (const SuiteOutcome& o : outcomes) {
    if (o.kind != StartKind::OFFSETS || o.offset_index < 0) continue;
    SuiteReachRow& row = score->reach.at(static_cast<size_t>(o.offset_index));
    for (SuiteShare* share : {&row.per_dataset.at(o.dataset), &row.all}) {
      ++share->runs;
      share->right += o.right ? 1 : 0;
    }
  }
  std::vector<std::string> families;
  for (const StartOffset& offset : score->offsets) {
    if (std::find(families.begin(), families.end(), offset.family) ==
        families.end()) {
      families.push_back(offset.family);
    }
  }
  for (const std::string& family : families) {
    std::vector<int> members;
    for (size_t k = 0; k < score->offsets.size(); ++k) {
      if (score->offsets[k].family == family) {
        members.push_back(static_cast<int>(k));
      }
    }
    SuiteFamilyReach reach;
    reach.family = family;
    for (size_t d = 0; d < num_datasets; ++d) {
      std::vector<SuiteShare> shares;
      for (const SuiteReachRow& row : score->reach) {
        shares.push_back(row.per_dataset[d]);
      }
      reach.per_dataset.push_back(Reach(members, shares, score->reach_share));
    }
    std::vector<SuiteShare> all;
    for (const SuiteReachRow& row : score->reach) all.push_back(row.all);
    reach.all = Reach(members, all, score->reach_share);
    score->family_reach.push_back(reach);
  }
}

}  // namespace

double AlongTrackErrorM(const Isometry3d& reference,
                        const Isometry3d& estimate) {
  const Vector3d t = reference.translation();
  if (t.norm() < 1e-3) return kNaN;
  return (estimate.translation() - t).dot(t.normalized());
}

SuiteOutcome ScoreSuiteRun(const SuiteRun& run,
                           const SuccessCriterion& criterion,
                           TerminationType termination,
                           const Isometry3d& estimate,
                           double time_ms) {
  SuiteOutcome outcome;
  outcome.dataset = run.dataset;
  outcome.kind = run.kind;
  outcome.offset_index = run.offset_index;
  outcome.termination = termination;
  outcome.error = ComputePoseError(run.reference_from_input, estimate);
  outcome.along_track_m = AlongTrackErrorM(run.reference_from_input, estimate);
  outcome.free = !run.free_directions.empty();
  outcome.right = outcome.free ? termination == TerminationType::DEGENERATE
                               : criterion.IsWithin(outcome.error);
  outcome.time_ms = time_ms;
  return outcome;
}

std::vector<TerminationType> AllTerminationTypes() {
  // The enum's values are contiguous from 0; TerminationTypeToString says
  // "UNKNOWN" past the last.
  std::vector<TerminationType> types;
  for (int k = 0;; ++k) {
    const auto type = static_cast<TerminationType>(k);
    if (std::strcmp(TerminationTypeToString(type), "UNKNOWN") == 0) break;
    types.push_back(type);
  }
  return types;
}

size_t ConfusionTable::Count(bool is_right, TerminationType type) const {
  const size_t k = TypeIndex(*this, type);
  return is_right ? right[k] : wrong[k];
}

size_t ConfusionTable::total() const {
  size_t n = 0;
  for (size_t k = 0; k < types.size(); ++k) n += right[k] + wrong[k];
  return n;
}

size_t ConfusionTable::total_right() const {
  size_t n = 0;
  for (const size_t count : right) n += count;
  return n;
}

size_t ConfusionTable::Reported(TerminationType type) const {
  return Count(true, type) + Count(false, type);
}

double ConfusionTable::Precision() const {
  return Ratio(Count(true, TerminationType::CONVERGENCE),
               Reported(TerminationType::CONVERGENCE));
}

double ConfusionTable::Recall() const {
  return Ratio(Count(true, TerminationType::CONVERGENCE), total_right());
}

double ConfusionTable::UsablePrecision() const {
  const size_t right_usable = Count(true, TerminationType::CONVERGENCE) +
                              Count(true, TerminationType::NO_CONVERGENCE);
  return Ratio(right_usable,
               Reported(TerminationType::CONVERGENCE) +
                   Reported(TerminationType::NO_CONVERGENCE));
}

double ConfusionTable::UsableRecall() const {
  return Ratio(Count(true, TerminationType::CONVERGENCE) +
                   Count(true, TerminationType::NO_CONVERGENCE),
               total_right());
}

double ConfusionTable::Success() const { return Ratio(total_right(), total()); }

ConfusionTable CountConfusion(const std::vector<SuiteOutcome>& outcomes) {
  ConfusionTable table;
  for (const SuiteOutcome& o : outcomes) {
    const size_t k = TypeIndex(table, o.termination);
    ++(o.right ? table.right : table.wrong)[k];
  }
  return table;
}

double SuiteShare::share() const { return Ratio(right, runs); }

SuiteScore ScoreSuite(const std::vector<std::string>& datasets,
                      const std::vector<StartKind>& starts,
                      const std::vector<StartOffset>& offsets,
                      const std::vector<SuiteSkips>& skips,
                      const std::vector<SuiteOutcome>& outcomes,
                      double reach_share) {
  CHECK_EQ(skips.size(), datasets.size());
  SuiteScore score;
  score.datasets = datasets;
  score.offsets = offsets;
  score.reach_share = reach_share;
  score.confusion = CountConfusion(outcomes);
  for (size_t d = 0; d < datasets.size(); ++d) {
    for (const StartKind kind : starts) {
      SuiteStartRow row;
      row.dataset = d;
      row.kind = kind;
      const auto skipped = skips[d].find(kind);
      row.skipped_pairs = skipped == skips[d].end() ? 0 : skipped->second;
      for (const SuiteOutcome& o : outcomes) {
        if (o.dataset != d || o.kind != kind) continue;
        const bool convergence = o.termination == TerminationType::CONVERGENCE;
        ++row.runs;
        row.right += o.right ? 1 : 0;
        row.convergence += convergence ? 1 : 0;
        row.wrong_convergence += convergence && !o.right ? 1 : 0;
      }
      if (row.runs > 0 || row.skipped_pairs > 0) score.by_start.push_back(row);
      if ((kind == StartKind::IDENTITY || kind == StartKind::PRIOR) &&
          row.runs > 0) {
        score.accuracy.push_back(Accuracy(d, kind, outcomes));
      }
    }
  }
  ScoreReach(outcomes, &score);
  return score;
}

const char* SuiteMeasureToString(SuiteMeasure measure) {
  switch (measure) {
    case SuiteMeasure::SUCCESS:
      return "success";
    case SuiteMeasure::PRECISION:
      return "precision";
    case SuiteMeasure::RECALL:
      return "recall";
    case SuiteMeasure::USABLE_PRECISION:
      return "usable_precision";
    case SuiteMeasure::USABLE_RECALL:
      return "usable_recall";
  }
  return "unknown";
}

bool StringToSuiteMeasure(std::string value, SuiteMeasure* result) {
  UpperCase(&value);
  MLNDT_STRING_TO_ENUM(SUCCESS, SuiteMeasure);
  MLNDT_STRING_TO_ENUM(PRECISION, SuiteMeasure);
  MLNDT_STRING_TO_ENUM(RECALL, SuiteMeasure);
  MLNDT_STRING_TO_ENUM(USABLE_PRECISION, SuiteMeasure);
  MLNDT_STRING_TO_ENUM(USABLE_RECALL, SuiteMeasure);
  return false;
}

double SuiteMeasureValue(const ConfusionTable& confusion,
                         SuiteMeasure measure) {
  switch (measure) {
    case SuiteMeasure::SUCCESS:
      return confusion.Success();
    case SuiteMeasure::PRECISION:
      return confusion.Precision();
    case SuiteMeasure::RECALL:
      return confusion.Recall();
    case SuiteMeasure::USABLE_PRECISION:
      return confusion.UsablePrecision();
    case SuiteMeasure::USABLE_RECALL:
      return confusion.UsableRecall();
  }
  return kNaN;
}

bool ParseSuiteTargets(const std::string& text,
                       std::vector<SuiteTarget>* targets,
                       std::string* error) {
  CHECK(targets != nullptr);
  CHECK(error != nullptr);
  targets->clear();
  std::stringstream list(text);
  std::string item;
  while (std::getline(list, item, ',')) {
    const size_t colon = item.find(':');
    SuiteTarget target;
    size_t used = 0;
    bool number = false;
    if (colon != std::string::npos) {
      try {
        target.minimum = std::stod(item.substr(colon + 1), &used);
        number = used == item.size() - colon - 1;
      } catch (...) {
      }
    }
    if (!number ||
        !StringToSuiteMeasure(item.substr(0, colon), &target.measure) ||
        !(target.minimum >= 0.0 && target.minimum <= 1.0)) {
      *error = "'" + item +
               "': expected MEASURE:minimum with MEASURE success, precision, "
               "recall, usable_precision or usable_recall and a minimum in "
               "[0, 1]";
      return false;
    }
    for (const SuiteTarget& other : *targets) {
      if (other.measure == target.measure) {
        *error = std::string("'") + SuiteMeasureToString(target.measure) +
                 "' given twice";
        return false;
      }
    }
    targets->push_back(target);
  }
  if (targets->empty() || text.back() == ',') {
    *error = "'" + text + "': expected MEASURE:minimum[,MEASURE:minimum...]";
    return false;
  }
  return true;
}

std::vector<std::string> MissedSuiteTargets(
    const ConfusionTable& confusion, const std::vector<SuiteTarget>& targets) {
  std::vector<std::string> missed;
  for (const SuiteTarget& target : targets) {
    const double value = SuiteMeasureValue(confusion, target.measure);
    if (value >= target.minimum) continue;
    std::ostringstream line;
    line << SuiteMeasureToString(target.measure) << " ";
    if (std::isfinite(value)) {
      line << value << " < " << target.minimum;
    } else {
      line << "undefined (no run to take the share of), target "
           << target.minimum;
    }
    missed.push_back(line.str());
  }
  return missed;
}

}  // namespace mlndt
