#pragma once

// mlndt_covariance's report: the consistency rows on stdout and as JSON
// (lab/eval/covariance_consistency.h), the --output_csv rows, and its
// --datasets list.

#include <sstream>
#include <string>
#include <vector>

#include "lab/eval/covariance_consistency.h"
#include "mlndt/registration/registration.h"
#include "tools/cli/json_output.h"

namespace mlndt {
namespace lab {

// The consistency as JSON, standard deviations in m and deg.
tools::Json ConsistencyJson(const Consistency& c);

// Three lines of the stdout report, headed by `label`.
void PrintRow(const std::string& label, const Consistency& c);

// --datasets=`text`: a comma-separated list of kitti and koide3.
bool ParseCovarianceDatasets(const std::string& text,
                             std::vector<std::string>* datasets,
                             std::string* error);

// The registrations of `datasets`: `starts` for each pair (KITTI has 7).
size_t CovarianceRegistrations(const std::vector<std::string>& datasets,
                               int starts);

// The --output_csv header line and one row a registration.
std::string CovarianceCsvHeader();
void AppendCovarianceCsvRow(const PairRuns& pair,
                            int start,
                            const RegistrationSummary& summary,
                            bool usable,
                            std::ostringstream* csv);

// Prints the rows of every pair and of every data set pooled, and adds
// them to *json ("pairs", and one member per data set).
void ReportConsistency(const std::vector<std::string>& datasets,
                       const std::vector<PairRuns>& pairs,
                       tools::Json* json);

}  // namespace lab
}  // namespace mlndt
