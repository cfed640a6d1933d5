#include "lab/experiments/report_files.h"

#include <cstdlib>
#include <filesystem>

#include "lab/report/gnuplot.h"
#include "lab/report/text_format.h"
#include "mlndt/common/atomic_file.h"

namespace mlndt {
namespace experiments {

void ReportFiles::Add(const std::string& relative_path, std::string content) {
  files_.emplace_back(relative_path, std::move(content));
}

std::string ReportFiles::AddFigure(const std::string& name,
                                   int width,
                                   int height,
                                   const std::string& body) {
  const std::string png = "figures/" + name + ".png";
  const std::string script = "figures/" + name + ".gp";
  Add(script,
      "# Run from the report folder: gnuplot " + script + "\n" +
          GnuplotPngHeader(width, height) +
          "set termoption noenhanced\n"
          "set datafile separator ','\n" +
          GnuplotSetOutput(png) + body);
  scripts_.push_back({script, png});
  return png;
}

bool ReportFiles::WriteAll(const std::string& out_dir,
                           bool plots,
                           const std::string& gnuplot,
                           std::string* error) const {
  namespace fs = std::filesystem;
  std::error_code ec;
  for (const char* sub : {"csv", "figures"}) {
    fs::create_directories(out_dir + "/" + sub, ec);
    if (ec) {
      *error = out_dir + "/" + sub + ": " + ec.message();
      return false;
    }
  }
  for (const auto& [path, content] : files_) {
    if (!WriteFileAtomically(out_dir + "/" + path, content, error))
      return false;
  }
  if (!plots) return true;
  for (const auto& [script, png] : scripts_) {
    if (!RenderGnuplot({gnuplot, out_dir, script, {png}}, error)) {
      return false;
    }
  }
  return true;
}

std::string MarkdownTable(const std::vector<std::string>& header,
                          const std::vector<std::vector<std::string>>& rows) {
  std::string out = "|";
  for (const std::string& h : header) out += " " + h + " |";
  out += "\n|";
  for (size_t i = 0; i < header.size(); ++i) out += "---|";
  out += "\n";
  for (const auto& row : rows) {
    out += "|";
    for (const std::string& cell : row) out += " " + cell + " |";
    out += "\n";
  }
  return out + "\n";
}

std::string CsvTable(const std::vector<std::string>& header,
                     const std::vector<std::vector<std::string>>& rows) {
  std::string out;
  for (size_t i = 0; i < header.size(); ++i)
    out += (i ? "," : "") + CsvField(header[i]);
  out += "\n";
  for (const auto& row : rows) {
    for (size_t i = 0; i < row.size(); ++i)
      out += (i ? "," : "") + CsvField(row[i]);
    out += "\n";
  }
  return out;
}

}  // namespace experiments
}  // namespace mlndt
