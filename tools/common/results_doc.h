#pragma once

// The reference of a result made from its table (result_table.h): the
// Markdown of docs/json_schema.md's result sections and the Python stub's
// class of the result (python/mlndt/__init__.pyi), each a block between
// "generated" markers that scripts/check_generated.sh compares with
// `mlndt_options --format=results_markdown|results_pyi`.

#include <string>
#include <vector>

#include "mlndt/common/result_table.h"

namespace mlndt {
namespace tools {

// `root` and the tables nested in it, each once, root first, then in the
// order they are first met.
std::vector<const ResultTable*> ResultTablesUnder(const ResultTable& root);

// One "### `Struct`" section per table under `root`: a row per field with
// its key, type, unit and meaning.
std::string ResultsMarkdown(const ResultTable& root);

// A TypedDict per nested table, then `class <python_class>` with one
// read-only property per field of `root` and todict().
std::string ResultsStub(const ResultTable& root,
                        const std::string& python_class,
                        const std::string& class_doc);

}  // namespace tools
}  // namespace mlndt
