#include "lab/eval/suite_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace mlndt {
namespace {

using Row = std::vector<std::string>;

// `value` with `precision` decimals; "–" when not finite.
std::string Fixed(double value, int precision) {
  if (!std::isfinite(value)) return "–";
  char text[64];
  std::snprintf(text, sizeof(text), "%.*f", precision, value);
  return text;
}

std::string Percent(double share) { return Fixed(100.0 * share, 1); }

// Display width of UTF-8 text (code points).
size_t Width(const std::string& text) {
  size_t n = 0;
  for (const char c : text) n += (static_cast<unsigned char>(c) & 0xC0) != 0x80;
  return n;
}

// A markdown table with padded columns.
std::string Table(const Row& header, const std::vector<Row>& rows) {
  std::vector<size_t> widths(header.size(), 3);
  for (size_t c = 0; c < header.size(); ++c) {
    widths[c] = std::max(widths[c], Width(header[c]));
  }
  for (const Row& row : rows) {
    for (size_t c = 0; c < row.size() && c < widths.size(); ++c) {
      widths[c] = std::max(widths[c], Width(row[c]));
    }
  }
  const auto line = [&](const Row& row) {
    std::string out = "|";
    for (size_t c = 0; c < widths.size(); ++c) {
      const std::string cell = c < row.size() ? row[c] : "";
      out += " " + cell + std::string(widths[c] - Width(cell), ' ') + " |";
    }
    return out + "\n";
  };
  std::string out = line(header) + "|";
  for (const size_t w : widths) out += std::string(w + 2, '-') + "|";
  out += "\n";
  for (const Row& row : rows) out += line(row);
  return out;
}

std::string Share(const SuiteShare& share) {
  if (share.runs == 0) return "–";
  return Percent(share.share()) + " (" + std::to_string(share.right) + "/" +
         std::to_string(share.runs) + ")";
}

// The values of an offset's label ("x=2" -> "2").
std::string OffsetValues(const StartOffset& offset) {
  const size_t equals = offset.label.find('=');
  return equals == std::string::npos ? offset.label
                                     : offset.label.substr(equals + 1);
}

std::string ReachCell(const SuiteScore& score, int reach) {
  if (reach == -2) return "–";
  if (reach == -1) return "none";
  return OffsetValues(score.offsets.at(static_cast<size_t>(reach)));
}

// "a of b" with the share, for the precision/recall lines.
std::string ShareLine(const char* name,
                      double value,
                      size_t numerator,
                      size_t denominator,
                      const char* of) {
  return std::string(name) + " " + Fixed(value, 4) + " (" +
         std::to_string(numerator) + " of " + std::to_string(denominator) +
         " " + of + ")";
}

}  // namespace

std::string FormatSuiteConfusion(const ConfusionTable& confusion) {
  Row header = {"pose"};
  for (const TerminationType type : confusion.types) {
    header.push_back(TerminationTypeToString(type));
  }
  header.push_back("total");
  std::vector<Row> rows;
  for (const bool right : {true, false}) {
    Row row = {right ? "right" : "wrong"};
    for (const TerminationType type : confusion.types) {
      row.push_back(std::to_string(confusion.Count(right, type)));
    }
    row.push_back(
        std::to_string(right ? confusion.total_right()
                             : confusion.total() - confusion.total_right()));
    rows.push_back(row);
  }
  Row total = {"total"};
  for (const TerminationType type : confusion.types) {
    total.push_back(std::to_string(confusion.Reported(type)));
  }
  total.push_back(std::to_string(confusion.total()));
  rows.push_back(total);

  const size_t right_convergence =
      confusion.Count(true, TerminationType::CONVERGENCE);
  const size_t right_usable =
      right_convergence +
      confusion.Count(true, TerminationType::NO_CONVERGENCE);
  const size_t usable = confusion.Reported(TerminationType::CONVERGENCE) +
                        confusion.Reported(TerminationType::NO_CONVERGENCE);
  std::string out = Table(header, rows);
  out += "CONVERGENCE: " +
         ShareLine("precision",
                   confusion.Precision(),
                   right_convergence,
                   confusion.Reported(TerminationType::CONVERGENCE),
                   "CONVERGENCE right") +
         ", " +
         ShareLine("recall",
                   confusion.Recall(),
                   right_convergence,
                   confusion.total_right(),
                   "right reported CONVERGENCE") +
         "\n";
  out += "usable (CONVERGENCE or NO_CONVERGENCE): " +
         ShareLine("precision",
                   confusion.UsablePrecision(),
                   right_usable,
                   usable,
                   "usable right") +
         ", " +
         ShareLine("recall",
                   confusion.UsableRecall(),
                   right_usable,
                   confusion.total_right(),
                   "right reported usable") +
         "\n";
  out += "success: " + Percent(confusion.Success()) + " % (" +
         std::to_string(confusion.total_right()) + " of " +
         std::to_string(confusion.total()) + " runs right)\n";
  return out;
}

std::string FormatSuiteStarts(const SuiteScore& score) {
  std::vector<Row> rows;
  for (const SuiteStartRow& r : score.by_start) {
    rows.push_back({score.datasets.at(r.dataset),
                    StartKindToString(r.kind),
                    std::to_string(r.runs),
                    std::to_string(r.right),
                    Percent(SuiteShare{r.runs, r.right}.share()),
                    std::to_string(r.convergence),
                    std::to_string(r.wrong_convergence),
                    std::to_string(r.skipped_pairs)});
  }
  return Table({"data set",
                "start",
                "runs",
                "right",
                "right %",
                "CONVERGENCE",
                "wrong CONVERGENCE",
                "pairs skipped"},
               rows);
}

std::string FormatSuiteAccuracy(const SuiteScore& score) {
  std::vector<Row> rows;
  for (const SuiteAccuracyRow& r : score.accuracy) {
    const bool any = r.right > 0;
    rows.push_back({score.datasets.at(r.dataset),
                    StartKindToString(r.kind),
                    std::to_string(r.right),
                    any ? Fixed(100.0 * r.rms_translation_m, 1) : "–",
                    Fixed(100.0 * r.mean_along_track_m, 1),
                    any ? Fixed(r.rms_rotation_deg, 3) : "–",
                    any ? Fixed(r.median_time_ms, 1) : "–"});
  }
  return Table({"data set",
                "start",
                "right runs",
                "RMS t [cm]",
                "mean along-track [cm]",
                "RMS rot [deg]",
                "median time [ms]"},
               rows);
}

std::string FormatSuiteReach(const SuiteScore& score) {
  if (score.offsets.empty()) return "";
  Row header = {"offset"};
  for (const std::string& name : score.datasets) header.push_back(name);
  header.push_back("all");
  std::vector<Row> rows;
  for (const SuiteReachRow& r : score.reach) {
    Row row = {score.offsets.at(static_cast<size_t>(r.offset_index)).label};
    for (const SuiteShare& share : r.per_dataset) row.push_back(Share(share));
    row.push_back(Share(r.all));
    rows.push_back(row);
  }
  std::string out = Table(header, rows);
  header[0] = "reach (>= " + Percent(score.reach_share) + " % right)";
  rows.clear();
  for (const SuiteFamilyReach& f : score.family_reach) {
    Row row = {f.family};
    for (const int reach : f.per_dataset)
      row.push_back(ReachCell(score, reach));
    row.push_back(ReachCell(score, f.all));
    rows.push_back(row);
  }
  return out + "\n" + Table(header, rows);
}

std::string FormatSuiteReport(const SuiteScore& score) {
  std::string out =
      "## Confusion: right (within tolerance of the reference) or wrong, by "
      "the reported termination\n\n" +
      FormatSuiteConfusion(score.confusion) +
      "\n## Per data set and start\n\n" + FormatSuiteStarts(score) +
      "\n## Accuracy of the right runs from the identity and the prior\n\n" +
      FormatSuiteAccuracy(score);
  if (!score.offsets.empty()) {
    out += "\n## Reach: right share per offset (offset ∘ reference)\n\n" +
           FormatSuiteReach(score);
  }
  return out;
}

}  // namespace mlndt
