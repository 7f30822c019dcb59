// SPDX-License-Identifier: MIT
// What a blind check on another reality writes (`flange diagnose --selftest --reality alt|third
// --out DIR`): selftest.json and selftest.md, and for a single pair the command that runs the
// same diagnosis on the files it wrote.
#pragma once

#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "diagnosis.h"

namespace flange::cli {

// "the same diagnosis: flange diagnose --real FIT --holdout HELDOUT --real-start ... --seed S
// --bootstrap B" for a pair whose sessions were written to `paths` (fit, held out, ...), started
// at those UTC times and were diagnosed with `options`' bootstrap seed and rounds (the start times
// and options the self-test gave the diagnosis: a bootstrap of another seed can decide a pick
// that stands at the edge of a margin otherwise).
void print_same_diagnosis(const std::vector<std::filesystem::path>& paths, double fit_start_utc_s,
                          double heldout_start_utc_s, const diagnose::DiagnoseOptions& options,
                          std::ostream& out);

// DIR/selftest.json and DIR/selftest.md; throws std::runtime_error when either cannot be written.
void write_blind_check_files(const std::filesystem::path& dir, const nlohmann::json& json,
                             const std::string& markdown, std::ostream& out);

}  // namespace flange::cli
