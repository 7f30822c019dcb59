// SPDX-License-Identifier: MIT
// One pair of the third reality's blind check, written out by `flange diagnose --selftest
// --reality third --case K` and diagnosed again as a user would with `flange diagnose --real` on
// its two sessions: the steps the tests of single third-reality pairs share.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "flange_in_process.h"

namespace flange::testing {

// Pair `pair` of the third reality's seed `seed` (40 pairs a seed) written to `dir`
// (pair_K_fit.csv, pair_K_heldout.csv, pair_K_truth.json, selftest.json); the run's outcome, its
// status 0 or 1 (1: an aim of the table missed, not an error) checked.
inline FlangeOutcome write_third_pair(int seed, int pair, const std::filesystem::path& dir) {
  const FlangeOutcome o = run_flange_captured(
      {"diagnose", "--selftest", "--reality", "third", "--pairs", "40", "--case",
       std::to_string(pair), "--seed", std::to_string(seed), "--jobs", "2", "--out", dir.string()});
  EXPECT_TRUE(o.status == 0 || o.status == 1) << o.err;
  return o;
}

// The pair's row of the blind check that write_third_pair wrote to `dir` (its selftest.json):
// its truth, claims, verdict and fitted values.
inline nlohmann::json third_pair_row(const std::filesystem::path& dir) {
  std::ifstream in(dir / "selftest.json");
  return nlohmann::json::parse(in)["pairs"].at(0);
}

// `flange diagnose --real` on pair `pair`'s two sessions in `dir` (with `options` after them),
// written to dir/diagnosis; its diagnosis.json, or null when the command failed (its error
// reported).
inline nlohmann::json diagnose_third_pair(const std::filesystem::path& dir, int pair,
                                          const std::vector<std::string>& options = {}) {
  const std::string stem = "pair_" + std::to_string(pair);
  std::vector<std::string> args = {"diagnose", "--real", (dir / (stem + "_fit.csv")).string(),
                                   "--holdout", (dir / (stem + "_heldout.csv")).string()};
  args.insert(args.end(), options.begin(), options.end());
  args.insert(args.end(), {"--out", (dir / "diagnosis").string()});
  const FlangeOutcome d = run_flange_captured(args);
  EXPECT_EQ(d.status, 0) << command_text(args) << ": " << d.err;
  if (d.status != 0) return nullptr;
  std::ifstream in(dir / "diagnosis" / "diagnosis.json");
  return nlohmann::json::parse(in);
}

}  // namespace flange::testing
