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

// A nested table described elsewhere (its own section, its own Python
// class): not repeated, and not entered.
struct DescribedResult {
  const ResultTable* table = nullptr;
  std::string python_class;  // The type of a property holding one.
};

// One "### `Struct`" section per table under `root`: a row per field with
// its key, type, unit and meaning.
std::string ResultsMarkdown(const ResultTable& root,
                            const std::vector<DescribedResult>& described = {});

// A TypedDict per nested table, then `class <python_class>` with one
// read-only property per field of `root` and todict(). A field holding a
// table of `described` has its Python class as its type.
std::string ResultsStub(const ResultTable& root,
                        const std::string& python_class,
                        const std::string& class_doc,
                        const std::vector<DescribedResult>& described = {});

}  // namespace tools
}  // namespace mlndt
