// SPDX-License-Identifier: MIT
// The Dut interface over a Verilated iir_core class. A template, because each Verilation has its
// own class: Viir_core in the per-set test binaries, Viir_core_<set> where several sets share one
// binary (bench/core_bench.cpp). Include after the generated header; the core must be Verilated
// with TRACE_FST.
#pragma once

#include <verilated.h>
#include <verilated_fst_c.h>

#include <filesystem>
#include <memory>
#include <type_traits>

#include "iir_core_dut.h"
#include "rtl_coverage.h"

namespace flange::tb {

template <class VerilatedCore>
class VerilatedDut final : public Dut {
 public:
  // With a non-empty `fst_path` every half cycle is dumped there (FST).
  explicit VerilatedDut(const std::filesystem::path& fst_path = {})
      : context_(std::make_unique<VerilatedContext>()) {
    // An RTL assertion is a test failure, reported by the harness, not a process abort.
    context_->fatalOnError(false);
    if (!fst_path.empty()) context_->traceEverOn(true);
    dut = std::make_unique<VerilatedCore>(context_.get(), "dut");
    if (!fst_path.empty()) {
      std::filesystem::create_directories(fst_path.parent_path());
      trace_ = std::make_unique<VerilatedFstC>();
      dut->trace(trace_.get(), 99);
      trace_->open(fst_path.string().c_str());
    }
    dut->clk_i = 0;
    dut->rst_ni = 0;
    dut->sample_valid_i = 0;
    dut->channel_i = 0;
    dut->flag_clear_i = 0;
    dut->eval();
    dump();
  }

  ~VerilatedDut() override {
    if (trace_) trace_->close();
    dut->final();
    write_rtl_coverage(*context_, "iir_core");
  }

  DutOutputs outputs() override {
    DutOutputs out;
    out.sample_bits = static_cast<std::uint32_t>(dut->sample_o);
    out.channel = static_cast<std::uint32_t>(dut->channel_o);
    out.sample_valid = dut->sample_valid_o != 0;
    out.busy = dut->busy_o != 0;
    out.overrun = static_cast<std::uint32_t>(dut->overrun_o);
    out.saturation = static_cast<std::uint32_t>(dut->saturation_o);
    out.channel_error = dut->channel_error_o != 0;
    return out;
  }

  void clock(const DutInputs& in) override {
    dut->rst_ni = in.rst_n ? 1 : 0;
    dut->sample_i = static_cast<std::remove_reference_t<decltype(dut->sample_i)>>(in.sample_bits);
    dut->channel_i = static_cast<std::remove_reference_t<decltype(dut->channel_i)>>(in.channel);
    dut->sample_valid_i = in.sample_valid ? 1 : 0;
    dut->flag_clear_i = in.flag_clear ? 1 : 0;
    dut->eval();
    dump();
    dut->clk_i = 1;
    dut->eval();
    dump();
    dut->clk_i = 0;
    dut->eval();
  }

  bool assertion_failed() const override { return context_->gotError(); }

 private:
  void dump() {
    context_->timeInc(1);
    if (trace_) trace_->dump(context_->time());
  }

  std::unique_ptr<VerilatedContext> context_;
  std::unique_ptr<VerilatedCore> dut;
  std::unique_ptr<VerilatedFstC> trace_;
};

}  // namespace flange::tb
