// SPDX-License-Identifier: MIT
// A pair of the third reality on disk: its two sessions in the recording format
// (t_s,clearance_mm,temp_c,voltage_v, six decimals) and its truth in a sidecar JSON that no
// diagnosis reads: every effect's class, shape, parameters and size, both sessions' protocols,
// loggers, ages and noise.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <vector>

#include "third_pairs.h"

namespace flange::third_reality {

nlohmann::json third_truth_json(const ThirdPairSpec& spec);

// Writes DIR/pair_K_fit.csv, DIR/pair_K_heldout.csv and DIR/pair_K_truth.json; returns the
// paths in that order. Throws std::runtime_error naming a file that cannot be written.
std::vector<std::filesystem::path> write_third_pair(const std::filesystem::path& dir,
                                                    const ThirdPairSpec& spec,
                                                    const ThirdPair& pair);

}  // namespace flange::third_reality
