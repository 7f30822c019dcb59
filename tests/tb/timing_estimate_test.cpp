// SPDX-License-Identifier: MIT
// The pre-route estimate on a hand-written netlist with the cell models of
// tests/data/synth/cell_models.il: known paths, known sums.
#include "timing_estimate.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

namespace flange::tb {
namespace {

CellTimingLibrary models() {
  std::ifstream in(std::string(FLANGE_SOURCE_DIR) + "/tests/data/synth/cell_models.il");
  std::ostringstream text;
  text << in.rdbuf();
  return CellTimingLibrary::parse(text.str());
}

// clk (2) and in (3) are pins; a_q (10) -> LUT2 I0, b_q (12) -> LUT2 I1, the LUT2 (11) -> b's D;
// a_q -> c's D; b's reset comes from a LUT2 on the pin `in` (not register to register).
const char* const kNetlist = R"({"modules": {"t": {
  "ports": {"clk": {"direction": "input", "bits": [2]}, "in": {"direction": "input", "bits": [3]}},
  "cells": {
    "a": {"type": "FDRE", "parameters": {"INIT": "0"},
          "port_directions": {"C": "input", "CE": "input", "D": "input", "R": "input", "Q": "output"},
          "connections": {"C": [2], "CE": ["1"], "D": [3], "R": ["0"], "Q": [10]}},
    "b": {"type": "FDRE", "parameters": {"INIT": "0"},
          "connections": {"C": [2], "CE": ["1"], "D": [11], "R": [14], "Q": [12]}},
    "c": {"type": "FDRE",
          "connections": {"C": [2], "CE": ["1"], "D": [10], "R": ["0"], "Q": [13]}},
    "$abc$1$lut": {"type": "LUT2", "parameters": {"INIT": "0110"},
          "connections": {"I0": [10], "I1": [12], "O": [11]}},
    "$abc$2$lut": {"type": "LUT2", "parameters": {"INIT": "0001"},
          "connections": {"I0": [3], "I1": [3], "O": [14]}}
  },
  "netnames": {
    "clk": {"hide_name": 0, "bits": [2]}, "in": {"hide_name": 0, "bits": [3]},
    "a_q": {"hide_name": 0, "bits": [10]}, "u.b_q": {"hide_name": 0, "bits": [12]},
    "b_q": {"hide_name": 0, "bits": [12]}, "c_q": {"hide_name": 0, "bits": [13]},
    "$techmap9$abc$1$lut\\sum_d.A": {"hide_name": 1, "bits": [11]}
  }}}})";

TEST(TimingEstimate, SumsCellsAndTheNetAllowanceOfTheWorstPath) {
  const TimingEstimate e = estimate_timing(kNetlist, "t", models(), 10000);
  ASSERT_EQ(e.clocks.size(), 1u);
  const ClockEstimate& c = e.clocks[0];
  EXPECT_EQ(c.clock, "clk");
  EXPECT_EQ(c.endpoints, 2);  // b's and c's D; a's D and b's R come from the pin
  // a: clock to Q 303, net a_q (2 loads) 500 + 2 * 10, LUT2 I0 238, net (1 load) 510, setup 0.
  EXPECT_EQ(c.worst_ps, 303 + 520 + 238 + 510);
  EXPECT_EQ(c.worst_cells_ps, 303 + 238);
  EXPECT_EQ(c.slack_ps, 10000 - c.worst_ps);
  EXPECT_EQ(e.worst_slack_ps(), c.slack_ps);

  ASSERT_EQ(e.worst_paths.size(), 2u);  // one per register: b, then c
  const TimingPath& p = e.worst_paths[0];
  EXPECT_EQ(p.from, "a_q");
  EXPECT_EQ(p.to, "b_q");  // the register's name, not u.b_q (deeper) nor the cell's id
  EXPECT_EQ(p.to_pin, "FDRE D");
  EXPECT_EQ(p.total_ps(), c.worst_ps);
  EXPECT_EQ(p.cells_ps, 303 + 238);
  EXPECT_EQ(p.nets_ps, 520 + 510);
  EXPECT_EQ(p.logic_levels, 1);
  ASSERT_EQ(p.steps.size(), 2u);
  EXPECT_EQ(p.steps[0].arc, "clock->Q");
  EXPECT_EQ(p.steps[0].fanout, 2);
  EXPECT_EQ(p.steps[1].type, "LUT2");
  EXPECT_EQ(p.steps[1].arc, "I0->O");
  EXPECT_EQ(p.steps[1].net, "~sum_d");  // the RTL name inside Yosys's hidden one
  EXPECT_EQ(e.worst_paths[1].to, "c_q");
  EXPECT_EQ(e.worst_paths[1].total_ps(), 303 + 520);
}

TEST(TimingEstimate, ChargesNoAllowanceWhenAskedForCellsOnly) {
  NetAllowance none;
  none.base_ps = 0;
  none.per_fanout_ps = 0;
  const TimingEstimate e = estimate_timing(kNetlist, "t", models(), 1000, none, 5);
  EXPECT_EQ(e.clocks[0].worst_ps, 303 + 238);
  EXPECT_EQ(e.clocks[0].slack_ps, 1000 - 541);
  EXPECT_EQ(NetAllowance{}.ps(1), 510);
  EXPECT_EQ(NetAllowance{}.ps(100), 1500);
}

TEST(TimingEstimate, RefusesACombinationalLoopAndAMissingTop) {
  std::string loop = kNetlist;
  // The first LUT's I1 from its own output: a loop.
  loop.replace(loop.find("\"I1\": [12], \"O\": [11]"), 21, "\"I1\": [11], \"O\": [11]");
  EXPECT_THROW(estimate_timing(loop, "t", models(), 10000), TimingEstimateError);
  EXPECT_THROW(estimate_timing(kNetlist, "other", models(), 10000), TimingEstimateError);
}

TEST(TimingEstimate, NamesCellTypesWithoutAModel) {
  std::string netlist = kNetlist;
  netlist.replace(netlist.find("\"type\": \"LUT2\", \"parameters\": {\"INIT\": \"0001\"}"), 46,
                  "\"type\": \"MYSTERY\", \"port_directions\": {\"I0\": \"input\", \"I1\": "
                  "\"input\", \"O\": \"output\"}");
  const TimingEstimate e = estimate_timing(netlist, "t", models(), 10000);
  EXPECT_EQ(e.types_without_model, std::vector<std::string>{"MYSTERY"});
}

}  // namespace
}  // namespace flange::tb
