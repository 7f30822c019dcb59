// SPDX-License-Identifier: MIT
#include "blind_check_files.h"

#include <fmt/format.h>

#include <fstream>
#include <stdexcept>

#include "utc_time.h"

namespace flange::cli {
namespace fs = std::filesystem;

void print_same_diagnosis(const std::vector<fs::path>& paths, double fit_start_utc_s,
                          double heldout_start_utc_s, const diagnose::DiagnoseOptions& options,
                          std::ostream& out) {
  for (const fs::path& path : paths) out << "  wrote " << path.string() << "\n";
  out << fmt::format(
      "  the same diagnosis: flange diagnose --real {} --holdout {} --real-start {} "
      "--holdout-start {} --seed {} --bootstrap {} --out DIR\n",
      paths.at(0).string(), paths.at(1).string(), format_utc_time(fit_start_utc_s),
      format_utc_time(heldout_start_utc_s), options.seed, options.bootstrap_rounds);
}

void write_blind_check_files(const fs::path& dir, const nlohmann::json& json,
                             const std::string& markdown, std::ostream& out) {
  std::ofstream json_file(dir / "selftest.json", std::ios::binary);
  json_file << json.dump(2) << "\n";
  std::ofstream md(dir / "selftest.md", std::ios::binary);
  md << markdown;
  json_file.close();
  md.close();
  if (!json_file || !md) throw std::runtime_error(dir.string() + ": cannot write");
  out << "  wrote " << (dir / "selftest.json").string() << " and " << (dir / "selftest.md").string()
      << "\n";
}

}  // namespace flange::cli
