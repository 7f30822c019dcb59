// SPDX-License-Identifier: MIT
#include "demo_command.h"

#include <ostream>
#include <sstream>

#include "cli.h"
#include "thesis_filters.h"

namespace flange::host {

CLI::App* add_demo_command(CLI::App& app, DemoOptions& options) {
  CLI::App* cmd = app.add_subcommand(
      "demo", "Design the thesis's two filters in every structure and report what holds");
  cmd->add_option("--out", options.out_dir, "folder for the generated sets")
      ->default_str("demo_out");
  return cmd;
}

int run_demo_command(const DemoOptions& options, std::ostream& out, std::ostream& err) {
  int failures = 0;
  for (const coeffs::ThesisFilter& filter : coeffs::thesis_filters()) {
    std::vector<std::string> args = filter.design;
    args.push_back("--out");
    args.push_back((options.out_dir / filter.set_name).string());
    out << "== " << filter.set_name << ": flange";
    for (const std::string& arg : filter.design) out << " " << arg;
    out << "\n";
    std::ostringstream messages;
    const int status = run_flange(args, out, messages);
    if (filter.expect_rejected) {
      out << "  (expected: the thesis's direct form does not survive quantisation; exit " << status
          << ": " << messages.str().substr(0, messages.str().find('\n')) << ")\n";
      if (status != 3) ++failures;
    } else if (status != 0) {
      err << messages.str();
      ++failures;
    }
    out << "\n";
  }
  if (failures > 0) {
    err << "flange demo: " << failures << " filter(s) did not behave as expected\n";
    return kExitFailure;
  }
  out << "demo: coefficient sets, ROM images, packages and plots in " << options.out_dir.string()
      << "/\n";
  return kExitOk;
}

}  // namespace flange::host
