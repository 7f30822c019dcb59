// SPDX-License-Identifier: MIT
#include "simulate_command.h"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <ostream>
#include <stdexcept>

#include "aliasing.h"
#include "bench_scenario.h"
#include "cli.h"
#include "effect_argument.h"
#include "effect_catalogue.h"
#include "fleet_alt_simulation.h"
#include "fleet_plan.h"
#include "fleet_simulation.h"
#include "loco_scenario.h"
#include "locomotive_manifest.h"
#include "sim_error.h"
#include "simulation.h"
#include "twin_file.h"
#include "version.h"

namespace flange::cli {

// What the command takes from the sensor twin and its scenarios (sim/).
using sim::alias_frequency_hz;
using sim::BadArgument;
using sim::BenchProtocol;
using sim::BenchScenario;
using sim::EffectSettings;
using sim::Locomotive;
using sim::LocoRun;
using sim::LocoScenario;
using sim::Scenario;
using sim::SensorTwin;
using sim::SimulationSummary;
using sim::TwinConfig;

namespace {

constexpr double kMaxSampleRateHz = 100000.0;
constexpr double kMaxDurationS = 366.0 * 86400.0;
constexpr double kMaxSamples = 1e9;          // about 45 GB of CSV: a typo, not a plan
constexpr double kBenchSampleRateHz = 6.0;   // thesis 4.3.1: the lab DAQ's 6 Hz
constexpr double kLocoSampleRateHz = 100.0;  // thesis 4.4.2: the multibody record's 100 Hz
constexpr double kLocoDurationS = 300.0;

void check_positive_finite(double value, double max, const std::string& name,
                           const std::string& unit) {
  if (!std::isfinite(value) || value <= 0.0 || value > max) {
    throw BadArgument(
        fmt::format("{} = {} is outside its valid range (0, {}] {}", name, value, max, unit));
  }
}

// Checks a number in (0, max] as the user typed it, so that "six", "nan" and "-1" get the same
// one-line message with the range.
CLI::Validator positive_up_to(double max, const std::string& unit) {
  return CLI::Validator(
      [max, unit](std::string& text) -> std::string {
        double value = 0.0;
        const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
        const bool parsed = error == std::errc() && end == text.data() + text.size();
        if (parsed && std::isfinite(value) && value > 0.0 && value <= max) return "";
        return fmt::format("{} is outside its valid range (0, {}] {}", text, max, unit);
      },
      fmt::format("(0, {}] {}", max, unit));
}

// Seeds are whole numbers 0 to 2^64 - 1; strtoull alone would wrap "-1" round to 2^64 - 1.
CLI::Validator seed_range() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        std::uint64_t value = 0;
        const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
        if (!text.empty() && error == std::errc() && end == text.data() + text.size()) return "";
        return text + " is not a whole number from 0 to 18446744073709551615";
      },
      "0 to 2^64-1");
}

// Checks a whole number in [low, high] as the user typed it ("3.5", "x" and "13" alike).
CLI::Validator whole_number_in(int low, int high) {
  return CLI::Validator(
      [low, high](std::string& text) -> std::string {
        int value = 0;
        const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
        const bool parsed = error == std::errc() && end == text.data() + text.size();
        if (parsed && value >= low && value <= high) return "";
        return fmt::format("{} is outside its valid range: a whole number {} to {}", text, low,
                           high);
      },
      fmt::format("{} to {}", low, high));
}

std::string list_hz(const std::vector<double>& frequencies) {
  std::string text;
  for (const double f : frequencies) text += fmt::format("{}{:.4g}", text.empty() ? "" : ", ", f);
  return text + " Hz";
}

// Where the periodic parts of the run land after sampling: the point of simulating at fs.
void report_aliasing(const TwinConfig& config, const SimulateOptions& options, double fs_hz,
                     const LocoRun& loco, std::ostream& out) {
  for (const EffectSettings& effect : config.effects) {
    if (effect.name == "mains_pickup") {
      std::vector<double> tones;
      std::vector<double> seen;
      for (int k = 1; k <= static_cast<int>(effect.params.at("harmonics")); ++k) {
        tones.push_back(k * effect.params.at("mains_hz"));
        seen.push_back(alias_frequency_hz(tones.back(), fs_hz));
      }
      out << "  mains_pickup: tones at " << list_hz(tones) << " appear at " << list_hz(seen)
          << "\n";
    }
    if (effect.name == "vibration" && effect.params.at("f_high_hz") > fs_hz / 2.0) {
      out << fmt::format(
          "  vibration: the {:.4g}-{:.4g} Hz band reaches above fs/2 = {:.4g} Hz "
          "and folds into 0-{:.4g} Hz\n",
          effect.params.at("f_low_hz"), effect.params.at("f_high_hz"), fs_hz / 2.0, fs_hz / 2.0);
    }
  }
  if (options.scenario == "loco") {
    const double mode_hz = lateral_natural_frequency_hz(loco.wheelset);
    out << fmt::format("  wheelset lateral mode: {:.3g} Hz undamped ({} leads){}\n", mode_hz,
                       loco.wheelset.leads,
                       mode_hz > fs_hz / 2.0 ? fmt::format(", above fs/2: it appears at {:.3g} Hz",
                                                           alias_frequency_hz(mode_hz, fs_hz))
                                             : ", below fs/2: sampled without aliasing");
  }
}

}  // namespace

CLI::App* add_simulate_command(CLI::App& app, SimulateOptions& options) {
  CLI::App* cmd = app.add_subcommand(
      "simulate",
      "Run a bench or locomotive scenario through the sensor twin into a recording, or a "
      "depot's fleet over days through the chain into a store");
  cmd->add_option("--scenario", options.scenario,
                  "bench: the thesis's heated micrometer protocol; loco: a locomotive run; fleet: "
                  "locomotives over days into --store (docs/fleet.md); fleet-alt: a second "
                  "fleet reality written into --out for the service path")
      ->required()
      ->check(CLI::IsMember({"bench", "loco", "fleet", "fleet-alt"}));
  cmd->add_option("--effect", options.effects,
                  "switch an effect on: NAME or NAME:key=value[,key=value...] (repeatable); "
                  "names and keys in docs/sensor_twin.md");
  cmd->add_option("--fs", options.fs_hz, "sample rate in Hz (bench 6, loco 100)")
      ->check(positive_up_to(kMaxSampleRateHz, "Hz"));
  cmd->add_option("--duration", options.duration_s, "record length in s (bench 6600, loco 300)")
      ->check(positive_up_to(kMaxDurationS, "s"));
  cmd->add_option("--seed", options.seed,
                  "seed of the twin's random numbers (required for bench and loco; fleet: 0 "
                  "when left out)")
      ->check(seed_range());
  cmd->add_option("--out", options.out,
                  "recording to write (CSV); with --wheels above 1 a folder for channel_XX.csv "
                  "and locomotive.json; fleet: the folder for the truth file and the bench "
                  "calibration (default: the SQLite store's folder)");
  cmd->add_option("--wheels", options.wheels,
                  "loco: wheels of the six-axle locomotive to simulate, each with its own "
                  "sensor (1 to 12; default 1, the leading left wheel)")
      ->check(whole_number_in(1, sim::kMaxWheels));
  cmd->add_option("--locomotives", options.locomotives,
                  "fleet: locomotives in the depot (1 to 100)")
      ->check(whole_number_in(1, sim::kMaxFleetLocomotives));
  cmd->add_option("--days", options.days, "fleet: days to simulate (1 to 3650)")
      ->check(whole_number_in(1, sim::kMaxFleetDays));
  cmd->add_option("--store", options.store,
                  "fleet: the store every run goes into: sqlite:PATH or postgresql://...");
  cmd->add_option("--twin", options.twin, "twin file (JSON) to start from");
  cmd->add_option("--save-twin", options.save_twin, "write the twin used to this JSON file");
  cmd->add_option("--calibration", options.calibration,
                  "a calibration (model.json from flange calibrate) as the twin's nominal model");
  return cmd;
}

namespace {

// The record every wheel shares: sample rate, length and twin, checked.
struct SimulationPlan {
  bool bench = false;
  BenchProtocol protocol;
  LocoRun loco;
  double fs_hz = 0.0;
  double duration_s = 0.0;
  TwinConfig config;
  std::uint64_t seed = 0;
  std::filesystem::path out;
};

SimulationPlan plan_simulation(const SimulateOptions& options) {
  SimulationPlan plan;
  plan.bench = options.scenario == "bench";
  if (!options.seed) throw BadArgument("--seed is required: a whole number 0 to 2^64-1");
  if (!options.out) throw BadArgument("--out is required: the recording (or folder) to write");
  plan.seed = *options.seed;
  plan.out = *options.out;
  for (const auto& [given, name] : {std::pair{options.locomotives.has_value(), "--locomotives"},
                                    {options.days.has_value(), "--days"},
                                    {options.store.has_value(), "--store"}}) {
    if (given) throw BadArgument(std::string(name) + ": only the fleet scenario takes it");
  }
  if (plan.bench && options.wheels) {
    throw BadArgument("--wheels: only the loco scenario has wheels; leave it out for bench");
  }
  plan.fs_hz = options.fs_hz.value_or(plan.bench ? kBenchSampleRateHz : kLocoSampleRateHz);
  plan.duration_s =
      options.duration_s.value_or(plan.bench ? plan.protocol.duration_s : kLocoDurationS);
  check_positive_finite(plan.fs_hz, kMaxSampleRateHz, "--fs", "Hz");
  check_positive_finite(plan.duration_s, kMaxDurationS, "--duration", "s");
  if (plan.fs_hz * plan.duration_s > kMaxSamples) {
    throw BadArgument(fmt::format("--fs x --duration = {:.3g} samples is above the limit of {:.0e}",
                                  plan.fs_hz * plan.duration_s, kMaxSamples));
  }
  plan.config = sim::twin_with_effects(options.twin, options.calibration, options.effects);
  return plan;
}

// The lines every simulate prints first: scenario, samples, twin.
void print_header(const SimulateOptions& options, const SimulationPlan& plan, std::int64_t samples,
                  std::ostream& out) {
  std::string effects;
  for (const EffectSettings& effect : plan.config.effects) {
    effects += (effects.empty() ? "" : ", ") + effect.name;
  }
  out << fmt::format("simulate: {} scenario, {} samples at {:.6g} Hz over {:.6g} s, seed {}\n",
                     options.scenario, samples, plan.fs_hz, plan.duration_s, plan.seed);
  out << fmt::format("  twin: noise {:.6g} V, effects: {}\n", plan.config.noise.voltage_std_v,
                     effects.empty() ? "none" : effects);
}

// One recording, as every scenario has always written it.
int simulate_recording(const SimulateOptions& options, const SimulationPlan& plan,
                       std::ostream& out) {
  std::unique_ptr<Scenario> scenario;
  if (plan.bench) {
    scenario = std::make_unique<BenchScenario>(plan.protocol, plan.fs_hz, plan.duration_s);
  } else {
    scenario = std::make_unique<LocoScenario>(plan.loco, plan.fs_hz, plan.duration_s);
  }
  SensorTwin twin(plan.config, plan.seed);
  std::ofstream csv(plan.out, std::ios::binary);
  if (!csv) throw std::runtime_error(plan.out.string() + ": cannot write the recording");
  const SimulationSummary summary = run_simulation(*scenario, twin, csv);
  csv.close();
  if (!csv) throw std::runtime_error(plan.out.string() + ": writing the recording failed");
  print_header(options, plan, summary.samples, out);
  out << fmt::format(
      "  reference clearance {:.3f} to {:.3f} mm, thermocouple {:.1f} to {:.1f} degC\n",
      summary.min_clearance_mm, summary.max_clearance_mm, summary.min_temp_c, summary.max_temp_c);
  out << fmt::format("  sensor output on a rail: {} samples at {:.6g} V, {} at {:.6g} V\n",
                     summary.clips.low, plan.config.nominal.v_min_v(), summary.clips.high,
                     plan.config.nominal.v_max_v());
  report_aliasing(plan.config, options, plan.fs_hz, plan.loco, out);
  out << "  wrote " << plan.out.string();
  if (options.save_twin) out << " and " << options.save_twin->string();
  out << "\n";
  return kExitOk;
}

// The manifest naming every wheel's file (host/recording/locomotive_manifest.h).
void write_manifest(const std::filesystem::path& dir, int wheels,
                    const std::vector<std::string>& command_line) {
  std::vector<host::ManifestChannel> channels;
  for (int channel = 0; channel < wheels; ++channel) {
    const sim::WheelPosition position = sim::wheel_position(channel);
    host::ManifestChannel entry;
    entry.channel = channel;
    entry.axle = position.axle;
    entry.side = position.side == sim::WheelSide::kLeft ? host::ManifestSide::kLeft
                                                        : host::ManifestSide::kRight;
    entry.file = host::channel_file_name(channel);
    channels.push_back(entry);
  }
  host::write_locomotive_manifest(dir / "locomotive.json", channels,
                                  runtime::generated_by(command_line));
}

void print_wheels(const Locomotive& locomotive, const std::vector<SimulationSummary>& summaries,
                  std::uint64_t seed, std::ostream& out) {
  out << "  ch  wheel         twin seed             d0_mm  wear_mm  reference_mm      "
         "rail_0V  rail_10V\n";
  double min_temp_c = summaries.front().min_temp_c;
  double max_temp_c = summaries.front().max_temp_c;
  for (int c = 0; c < locomotive.wheels(); ++c) {
    const SimulationSummary& s = summaries[static_cast<std::size_t>(c)];
    const sim::WheelPosition position = sim::wheel_position(c);
    out << fmt::format(
        "  {:>2}  axle {} {:<5}  {:<20}  {:>5.3f}  {:>7.3f}  {:>6.3f} to {:>6.3f}  "
        "{:>7}  {:>8}\n",
        c, position.axle, sim::side_name(position.side), sim::wheel_seed(seed, c),
        locomotive.flange(c).initial_clearance_mm, locomotive.flange(c).wear_over_run_mm,
        s.min_clearance_mm, s.max_clearance_mm, s.clips.low, s.clips.high);
    min_temp_c = std::min(min_temp_c, s.min_temp_c);
    max_temp_c = std::max(max_temp_c, s.max_temp_c);
  }
  out << fmt::format("  thermocouples {:.1f} to {:.1f} degC (one brake heating for every wheel)\n",
                     min_temp_c, max_temp_c);
}

// Every wheel of the locomotive, each through its own twin, into DIR/channel_XX.csv, and
// DIR/locomotive.json naming them.
int simulate_locomotive(const SimulateOptions& options, const SimulationPlan& plan,
                        const std::vector<std::string>& command_line, std::ostream& out) {
  const std::filesystem::path& dir = plan.out;
  std::error_code error;
  std::filesystem::create_directories(dir, error);
  if (error || !std::filesystem::is_directory(dir)) {
    throw std::runtime_error("--out " + dir.string() + ": cannot create the folder");
  }
  Locomotive locomotive(plan.loco, *options.wheels, plan.fs_hz, plan.duration_s);
  std::vector<SensorTwin> twins;
  std::vector<std::ofstream> files;
  std::vector<std::ostream*> streams;
  for (int c = 0; c < locomotive.wheels(); ++c) {
    twins.emplace_back(plan.config, sim::wheel_seed(plan.seed, c));
    files.emplace_back(dir / host::channel_file_name(c), std::ios::binary);
    if (!files.back()) {
      throw std::runtime_error((dir / host::channel_file_name(c)).string() +
                               ": cannot write the recording");
    }
  }
  streams.reserve(files.size());
  for (std::ofstream& file : files) streams.push_back(&file);
  const std::vector<SimulationSummary> summaries =
      run_locomotive_simulation(locomotive, twins, streams);
  for (int c = 0; c < locomotive.wheels(); ++c) {
    std::ofstream& file = files[static_cast<std::size_t>(c)];
    file.close();
    if (!file) {
      throw std::runtime_error((dir / host::channel_file_name(c)).string() +
                               ": writing the recording failed");
    }
  }
  write_manifest(dir, locomotive.wheels(), command_line);
  print_header(options, plan, locomotive.sample_count(), out);
  print_wheels(locomotive, summaries, plan.seed, out);
  report_aliasing(plan.config, options, plan.fs_hz, plan.loco, out);
  out << "  wrote " << (dir / "locomotive.json").string() << " and " << locomotive.wheels()
      << " recordings beside it";
  if (options.save_twin) out << ", and " << options.save_twin->string();
  out << "\n";
  return kExitOk;
}

}  // namespace

int run_simulate_command(const SimulateOptions& options,
                         const std::vector<std::string>& command_line, std::ostream& out) {
  if (options.scenario == "fleet") return run_fleet_simulation(options, command_line, out);
  if (options.scenario == "fleet-alt") return run_fleet_alt_simulation(options, command_line, out);
  const SimulationPlan plan = plan_simulation(options);
  if (options.save_twin) save_twin(plan.config, *options.save_twin);
  if (options.wheels.value_or(1) > 1) return simulate_locomotive(options, plan, command_line, out);
  return simulate_recording(options, plan, out);
}

}  // namespace flange::cli
