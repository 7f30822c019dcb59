// SPDX-License-Identifier: MIT
// `flange demo`: the main job, end to end on the thesis's filters.
#pragma once

#include <CLI/CLI.hpp>
#include <filesystem>
#include <iosfwd>

namespace flange::cli {

struct DemoOptions {
  std::filesystem::path out_dir = "demo_out";
};

CLI::App* add_demo_command(CLI::App& app, DemoOptions& options);
int run_demo_command(const DemoOptions& options, std::ostream& out, std::ostream& err);

}  // namespace flange::cli
