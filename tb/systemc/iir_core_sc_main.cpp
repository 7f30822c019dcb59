// SPDX-License-Identifier: MIT
// The SystemC bench of the IIR core at its real timing: a 100 MHz sc_clock, a sample source that
// strobes EN once per sample period (the sensor's, or a compressed one), the Verilated core
// (`dut`), an output monitor and a scoreboard that checks every output against the bit-accurate
// model. Built once per coefficient set (tb/systemc/CMakeLists.txt); docs/systemc.md.
//
// Prints one line on stdout:
//   systemc: SET: N samples, M mismatches, latency L cycles, T simulated at 100 MHz, sample
//   period P cycles (true period Q cycles at FS Hz: time compressed Fx), W s wall
// and exits 0, 1 on a mismatch or an RTL assertion, 2 on a bad argument.
#include <Viir_core.h>
#include <fmt/format.h>
#include <verilated.h>
#include <verilated_fst_sc.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <systemc>
#include <vector>

#include "cosim_run.h"
#include "iir_core_dut.h"
#include "output_monitor.h"
#include "sample_source.h"
#include "scoreboard.h"

namespace {

namespace sc = flange::tb::sc;

constexpr double kClockHz = 100e6;  // the Basys-3 oscillator
constexpr double kClockPeriodNs = 1e9 / kClockHz;
// After the last output is due: a few more cycles, so that an output one or two cycles late is
// still seen (and reported as late rather than missing).
constexpr std::uint64_t kTailCycles = 4;

struct BenchOptions {
  std::size_t samples = 1000;
  std::uint64_t period_cycles = 1000;  // clock cycles per sample
  bool true_period = false;            // use round(100 MHz / fs) instead of period_cycles
  std::string stimulus = "random";
  std::uint64_t seed = 1;
  std::filesystem::path trace;  // FST file, empty for none
  std::string plant_fault = "none";
  std::uint64_t plant_at = 0;
};

std::string reproduce_command(int argc, char* argv[]) {
  std::string command;
  for (int i = 0; i < argc; ++i) command += (i ? " " : "") + std::string(argv[i]);
  return command;
}

std::string format_sim_time(double seconds) {
  if (seconds >= 1.0) return fmt::format("{:.3f} s", seconds);
  if (seconds >= 1e-3) return fmt::format("{:.3f} ms", seconds * 1e3);
  return fmt::format("{:.3f} us", seconds * 1e6);
}

// The core's cycles per sample and latency, and the sample period in clock cycles: the true
// one (100 MHz / fs) or a compressed one.
struct BenchTiming {
  std::uint64_t cycles_per_sample = 0;
  std::uint64_t latency = 0;
  std::uint64_t true_period_cycles = 0;
  std::uint64_t period = 0;
  double compression = 0.0;  // true period over the period used
};

BenchTiming bench_timing(const BenchOptions& options, const flange::model::CoreConfig& config,
                         const flange::model::FloatDesign& design) {
  const flange::model::IirCore timing_model(config);  // only asked for its timing
  BenchTiming timing;
  timing.cycles_per_sample = static_cast<std::uint64_t>(timing_model.cycles_per_sample());
  timing.latency = static_cast<std::uint64_t>(timing_model.latency_cycles());
  timing.true_period_cycles = static_cast<std::uint64_t>(std::llround(kClockHz / design.fs_hz));
  timing.period = options.true_period ? timing.true_period_cycles : options.period_cycles;
  if (timing.period < timing.cycles_per_sample) {
    throw std::invalid_argument(
        fmt::format("--period-cycles: must be at least the core's {} cycles per sample, got {}",
                    timing.cycles_per_sample, timing.period));
  }
  timing.compression =
      static_cast<double>(timing.true_period_cycles) / static_cast<double>(timing.period);
  return timing;
}

sc::SampleSchedule sample_schedule(const BenchOptions& options,
                                   const flange::tb::BuiltCoeffSet& set,
                                   const flange::model::CoreConfig& config,
                                   const flange::model::FloatDesign& design, std::uint64_t period) {
  flange::tb::CosimOptions stimulus_options;
  stimulus_options.coeffs = set.filter_json;
  stimulus_options.samples = options.samples;
  stimulus_options.seed = options.seed;
  stimulus_options.stimulus = options.stimulus;
  sc::SampleSchedule schedule;
  schedule.samples = flange::tb::cosim_samples(stimulus_options, config, design);
  schedule.sample_width = config.sample_width;
  schedule.period_cycles = period;
  return schedule;
}

sc::PlantedFault planted_fault(const BenchOptions& options) {
  sc::PlantedFault fault;
  if (options.plant_fault == "value") fault.kind = sc::PlantedFault::Kind::kWrongValue;
  if (options.plant_fault == "late") fault.kind = sc::PlantedFault::Kind::kOneCycleLate;
  fault.output_index = options.plant_at;
  return fault;
}

// The signals and modules of the bench, wired: source -> dut -> monitor, and both ends into the
// scoreboard. Members are constructed in the order they are declared.
struct Bench {
  Bench(const sc::SampleSchedule& schedule, const flange::model::CoreConfig& config,
        const sc_core::sc_time& clock_period, const sc::PlantedFault& fault);

  sc_core::sc_clock clk;  // first rising edge at time 0
  sc_core::sc_signal<bool> rst_n;
  sc_core::sc_signal<std::uint32_t> sample_in;
  sc_core::sc_signal<bool> sample_valid_in;
  sc_core::sc_signal<bool> flag_clear;  // never raised: flags stay sticky
  sc_core::sc_signal<std::uint32_t> sample_out;
  sc_core::sc_signal<bool> sample_valid_out;
  sc_core::sc_signal<bool> busy;
  sc_core::sc_signal<bool> overrun;
  sc_core::sc_signal<bool> saturation;
  // The one-channel sets this bench runs: channel 0 in, channel_o and channel_error_o unwatched.
  sc_core::sc_signal<bool> channel_in;
  sc_core::sc_signal<bool> channel_out;
  sc_core::sc_signal<bool> channel_error;
  // Deep enough for a sample period: the scoreboard empties both every delta cycle.
  sc_core::sc_fifo<sc::InputRecord> applied;
  sc_core::sc_fifo<sc::OutputRecord> observed;

  sc::SampleSource source;
  const std::unique_ptr<Viir_core> dut;
  sc::OutputMonitor monitor;
  sc::Scoreboard scoreboard;
};

Bench::Bench(const sc::SampleSchedule& schedule, const flange::model::CoreConfig& config,
             const sc_core::sc_time& clock_period, const sc::PlantedFault& fault)
    : clk("clk", clock_period),
      rst_n("rst_n", false),
      sample_in("sample_in"),
      sample_valid_in("sample_valid_in", false),
      flag_clear("flag_clear", false),
      sample_out("sample_out"),
      sample_valid_out("sample_valid_out"),
      busy("busy"),
      overrun("overrun"),
      saturation("saturation"),
      channel_in("channel_in", false),
      channel_out("channel_out"),
      channel_error("channel_error"),
      applied("applied", 16),
      observed("observed", 16),
      source("source", schedule),
      dut(std::make_unique<Viir_core>("dut")),
      monitor("monitor", config.sample_width, clock_period, fault),
      scoreboard("scoreboard", config, clock_period) {
  source.clk(clk);
  source.rst_n(rst_n);
  source.sample(sample_in);
  source.sample_valid(sample_valid_in);
  source.applied(applied);

  dut->clk_i(clk);
  dut->rst_ni(rst_n);
  dut->sample_i(sample_in);
  dut->sample_valid_i(sample_valid_in);
  dut->flag_clear_i(flag_clear);
  dut->sample_o(sample_out);
  dut->sample_valid_o(sample_valid_out);
  dut->busy_o(busy);
  dut->overrun_o(overrun);
  dut->saturation_o(saturation);
  dut->channel_i(channel_in);
  dut->channel_o(channel_out);
  dut->channel_error_o(channel_error);

  monitor.clk(clk);
  monitor.sample(sample_out);
  monitor.sample_valid(sample_valid_out);
  monitor.busy(busy);
  monitor.overrun(overrun);
  monitor.saturation(saturation);
  monitor.observed(observed);

  scoreboard.applied(applied);
  scoreboard.observed(observed);
}

// After elaboration; nullptr when no trace was asked for.
std::unique_ptr<VerilatedFstSc> open_trace(const std::filesystem::path& path, Viir_core& dut) {
  if (path.empty()) return nullptr;
  if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path());
  auto trace = std::make_unique<VerilatedFstSc>();
  dut.trace(trace.get(), 99);
  trace->open(path.string().c_str());
  return trace;
}

// Simulates up to `end`; returns the wall-clock seconds it took.
double simulate_until(const sc_core::sc_time& end) {
  const auto wall_start = std::chrono::steady_clock::now();
  sc_core::sc_start(end - sc_core::sc_time_stamp());
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
}

std::vector<std::string> bench_failures(const sc::ScoreboardSummary& summary, bool rtl_assertion,
                                        bool source_done, std::size_t samples,
                                        std::uint64_t latency) {
  std::vector<std::string> failures;
  if (!summary.first_mismatch.empty()) {
    failures.push_back("first mismatch: " + summary.first_mismatch);
  }
  if (rtl_assertion) failures.push_back("an RTL assertion fired (see above)");
  if (!source_done) failures.push_back("the run ended before every sample was strobed");
  if (summary.outputs_checked != samples) {
    failures.push_back(fmt::format("{} outputs for {} samples", summary.outputs_checked, samples));
  }
  if (summary.min_latency_cycles != latency || summary.max_latency_cycles != latency) {
    failures.push_back(fmt::format("latency {}..{} cycles, the model's is {}",
                                   summary.min_latency_cycles, summary.max_latency_cycles,
                                   latency));
  }
  return failures;
}

void print_summary_line(const std::string& set_name, const sc::ScoreboardSummary& summary,
                        const BenchTiming& timing, double fs_hz, double wall_s) {
  const std::string latency_text =
      summary.min_latency_cycles == summary.max_latency_cycles
          ? fmt::format("{}", summary.min_latency_cycles)
          : fmt::format("{}..{}", summary.min_latency_cycles, summary.max_latency_cycles);
  std::cout << fmt::format(
      "systemc: {}: {} samples, {} mismatches, latency {} cycles (model {}), {} simulated at "
      "100 MHz, sample period {} cycles (true period {} cycles at {:g} Hz: time compressed "
      "{:.0f}x), {:.2f} s wall\n",
      set_name, summary.outputs_checked, summary.mismatches, latency_text, timing.latency,
      format_sim_time(sc_core::sc_time_stamp().to_seconds()), timing.period,
      timing.true_period_cycles, fs_hz, timing.compression, wall_s);
}

int run_bench(const BenchOptions& options, const std::string& reproduce) {
  const flange::tb::BuiltCoeffSet& set = flange::tb::built_coeff_set();
  const flange::model::CoreConfig config = flange::model::load_core_config(set.filter_json);
  const flange::model::FloatDesign design = flange::model::load_float_design(set.filter_json);
  const BenchTiming timing = bench_timing(options, config, design);
  const sc::SampleSchedule schedule = sample_schedule(options, set, config, design, timing.period);
  const sc::PlantedFault fault = planted_fault(options);

  // An RTL assertion is counted and reported here, not a process abort.
  Verilated::threadContextp()->fatalOnError(false);
  if (!options.trace.empty()) Verilated::traceEverOn(true);

  const sc_core::sc_time clock_period(kClockPeriodNs, sc_core::SC_NS);
  Bench bench(schedule, config, clock_period, fault);
  sc_core::sc_start(sc_core::SC_ZERO_TIME);  // elaborate: a trace can only open after it
  const std::unique_ptr<VerilatedFstSc> trace = open_trace(options.trace, *bench.dut);

  const std::uint64_t end_cycle = schedule.last_strobe_cycle() + timing.latency + kTailCycles;
  const double wall_s = simulate_until(clock_period * static_cast<double>(end_cycle));
  bench.dut->final();
  if (trace) trace->close();

  const sc::ScoreboardSummary summary = bench.scoreboard.finish(sc_core::sc_time_stamp());
  const bool rtl_assertion = Verilated::threadContextp()->gotError();
  const std::vector<std::string> failures = bench_failures(
      summary, rtl_assertion, bench.source.done(), schedule.samples.size(), timing.latency);
  for (const std::string& failure : failures) std::cerr << "systemc: " << failure << "\n";
  if (!failures.empty()) std::cerr << "systemc: reproduce with: " << reproduce << "\n";
  print_summary_line(set.name, summary, timing, design.fs_hz, wall_s);
  return failures.empty() ? 0 : 1;
}

}  // namespace

int sc_main(int argc, char* argv[]) {
  BenchOptions options;
  CLI::App app{
      "SystemC bench of iir_core at its real timing (100 MHz clock, EN at the sample period), "
      "every output checked against the bit-accurate model"};
  app.add_option("--samples", options.samples, "samples to strobe")
      ->check(CLI::Range(std::size_t{1}, std::size_t{100'000'000}));
  auto* period = app.add_option("--period-cycles", options.period_cycles,
                                "clock cycles per sample (a compressed sample period); at least "
                                "the core's cycles per sample")
                     ->check(CLI::Range(std::uint64_t{1}, std::uint64_t{2'147'483'647}));
  app.add_flag("--true-period", options.true_period,
               "strobe at the set's real sample rate: round(100 MHz / fs) cycles per sample")
      ->excludes(period);
  app.add_option("--stimulus", options.stimulus,
                 "random|fullscale|sweep|step|impulse|FILE.csv (as flange cosim)");
  app.add_option("--seed", options.seed, "seed of the random stimuli");
  app.add_option("--trace", options.trace, "FST waveform file (logs/ is git-ignored)");
  app.add_option("--plant-fault", options.plant_fault,
                 "bench self-test: the monitor reports one output wrong (value) or a cycle late "
                 "(late); the run must then fail")
      ->check(CLI::IsMember({"none", "value", "late"}));
  app.add_option("--plant-at", options.plant_at, "index of the output that gets the fault");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  try {
    return run_bench(options, reproduce_command(argc, argv));
  } catch (const flange::model::FilterJsonError& e) {
    std::cerr << "systemc: " << e.what() << "\n";
    return 2;
  } catch (const std::invalid_argument& e) {
    std::cerr << "systemc: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "systemc: " << e.what() << "\n";
    return 1;
  }
}

// Our own main instead of libsystemc's: the kernel prints its banner on stderr when the simulation
// starts unless SC_COPYRIGHT_MESSAGE=DISABLE, and the bench's output is one summary line.
int main(int argc, char* argv[]) {
  setenv("SC_COPYRIGHT_MESSAGE", "DISABLE", /*overwrite=*/0);
  return sc_core::sc_elab_and_sim(argc, argv);
}
