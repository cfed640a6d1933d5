#include "tools/cli/verdict_counts_json.h"

namespace mlndt {
namespace tools {

Json VerdictCountsJson(const VerdictCounts& counts) {
  Json json = Json::object();
  for (const TerminationType type : VerdictCounts::Verdicts()) {
    json[TerminationTypeToString(type)] = counts.count(type);
  }
  return json;
}

}  // namespace tools
}  // namespace mlndt
