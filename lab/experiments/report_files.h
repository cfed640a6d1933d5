#pragma once

// The files of the report folder OUT: README_RESULTS.md, csv/*.csv and
// figures/*.{gp,png}. Every figure's script reads only CSVs of csv/ and is
// run from OUT (`cd OUT && gnuplot figures/NAME.gp` regenerates it).

#include <string>
#include <utility>
#include <vector>

namespace mlndt {
namespace experiments {

class ReportFiles {
 public:
  // OUT/relative_path, written by WriteAll (atomically).
  void Add(const std::string& relative_path, std::string content);
  // figures/NAME.gp with a PNG header of width x height, the output
  // figures/NAME.png, then `body`; returns "figures/NAME.png".
  std::string AddFigure(const std::string& name,
                        int width,
                        int height,
                        const std::string& body);

  // Writes every file, then (when `plots`) runs `gnuplot` on every script.
  // False with *error naming the file or script.
  bool WriteAll(const std::string& out_dir,
                bool plots,
                const std::string& gnuplot,
                std::string* error) const;

 private:
  std::vector<std::pair<std::string, std::string>> files_;
  // (script, figure), relative paths.
  std::vector<std::pair<std::string, std::string>> scripts_;
};

// A markdown table.
std::string MarkdownTable(const std::vector<std::string>& header,
                          const std::vector<std::vector<std::string>>& rows);

// A CSV of the same cells (the numbers as the report prints them).
std::string CsvTable(const std::vector<std::string>& header,
                     const std::vector<std::vector<std::string>>& rows);

}  // namespace experiments
}  // namespace mlndt
