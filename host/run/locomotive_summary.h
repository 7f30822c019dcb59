// SPDX-License-Identifier: MIT
// What `flange run --manifest` says about each wheel and which wheel is the worst: the table it
// prints and the summary.json it writes.
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>

#include "locomotive_run.h"
#include "thresholds.h"

namespace flange::host {

// A channel's alarms at a glance.
struct AlarmDigest {
  AlarmLevel highest = AlarmLevel::kNone;  // the highest level raised during the run
  std::optional<double> first_warning_s;   // when warning was first raised
  std::optional<double> first_critical_s;  // when critical was first raised
  std::size_t wear_steps = 0;              // wear-step events (eq. 3.38)
};

AlarmDigest digest_alarms(const RunSummary& summary);

// Index (into run.channels) of the worst wheel: the highest alarm level raised, reached
// earliest; among wheels without alarms the largest settled filtered clearance (the thinnest
// flange seen). None when no channel has a settled row.
std::optional<std::size_t> worst_channel(const LocomotiveRun& run);

// The table printed on stdout: one row per channel (channel, wheel, rows, flagged rows, final,
// smallest and largest filtered clearance, final alarm, when warning and critical were first
// raised, wear steps), then the worst wheel.
std::string locomotive_table_text(const LocomotiveRun& run);

// Writes `path` (summary.json): the run's inputs, the worst channel and, per channel, its wheel,
// files, row counts, filtered clearance, every alarm event and the errors against the reference.
void write_locomotive_summary_json(const std::filesystem::path& path, const LocomotiveRun& run,
                                   const std::string& generated_by);

}  // namespace flange::host
