// SPDX-License-Identifier: MIT
#include "fleet_simulation.h"

#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <ostream>
#include <sstream>

#include "bench_scenario.h"
#include "calibration.h"
#include "cli.h"
#include "content_sha256.h"
#include "data_dir.h"
#include "fleet_day.h"
#include "fleet_plan.h"
#include "fleet_truth_file.h"
#include "gaussian_source.h"
#include "input_error.h"
#include "locomotive_run.h"
#include "locomotive_run_record.h"
#include "locomotive_summary.h"
#include "locomotive_wheels.h"
#include "recording_csv.h"
#include "sim_error.h"
#include "simulation.h"
#include "store.h"
#include "store_url.h"
#include "twin_file.h"
#include "version.h"

namespace flange::cli {
namespace {

namespace fs = std::filesystem;
using sim::BadArgument;

constexpr std::uint64_t kBenchStream = 7;   // the depot's bench session: a stream of --seed
constexpr double kServiceStartHours = 6.0;  // every day's recording starts at 06:00 UTC
constexpr double kMaintenanceHours = 12.0;  // the depot's lathe works at noon on a depot day

// Everything a fleet run shares.
struct Fleet {
  sim::FleetTruth truth;
  sim::FleetRecording recording;
  sim::TwinConfig twin;
  fs::path dir;       // truth file, bench session, calibration
  fs::path days_dir;  // one day's recordings at a time
  host::RunOptions chain;
  std::unique_ptr<host::Store> store;
  std::optional<std::int64_t> calibration_id;
};

int required(const std::optional<int>& value, const char* name, int max) {
  if (!value) {
    throw BadArgument(
        fmt::format("{} is required with --scenario fleet: a whole number 1 to {}", name, max));
  }
  return *value;
}

void refuse_loco_options(const SimulateOptions& options) {
  for (const auto& [given, name] : {std::pair{options.wheels.has_value(), "--wheels"},
                                    {options.fs_hz.has_value(), "--fs"},
                                    {options.duration_s.has_value(), "--duration"},
                                    {options.calibration.has_value(), "--calibration"}}) {
    if (given) {
      throw BadArgument(fmt::format(
          "{}: the fleet scenario records every wheel at 6 Hz for 240 s with the thesis's "
          "sensor; leave it out",
          name));
    }
  }
}

// The folder beside the store: --out, or the SQLite file's folder.
fs::path fleet_folder(const SimulateOptions& options, const host::StoreUrl& url) {
  if (options.out) return *options.out;
  if (url.backend != host::StoreBackend::kSqlite) {
    throw BadArgument("--out is required with a postgresql store: the folder for the truth file");
  }
  const fs::path parent = fs::path(url.target).parent_path();
  return parent.empty() ? fs::path(".") : parent;
}

std::string utc_at(int day, double hours) {
  const int minutes = static_cast<int>(std::lround(hours * 60.0));
  return fmt::format("{}T{:02d}:{:02d}:00Z", sim::iso_date(day), minutes / 60, minutes % 60);
}

host::WheelKey wheel_key(const std::string& locomotive, int channel) {
  const sim::WheelPosition position = sim::wheel_position(channel);
  return {locomotive, position.axle, sim::side_name(position.side)};
}

// The depot's bench session through the twin, fitted, into the store and beside it.
void calibrate_depot(Fleet& fleet, std::uint64_t seed) {
  const fs::path bench_csv = fleet.dir / "fleet_bench.csv";
  {
    const sim::BenchProtocol protocol;
    sim::BenchScenario bench(protocol, fleet.recording.fs_hz, protocol.duration_s);
    sim::SensorTwin twin(fleet.twin, sim::derive_seed(seed, kBenchStream));
    std::ofstream csv(bench_csv, std::ios::binary);
    sim::run_simulation(bench, twin, csv);
    if (!csv) throw std::runtime_error(bench_csv.string() + ": cannot write the bench session");
  }
  const host::Calibration calibration = host::calibrate_database(bench_csv.string(), {});
  const fs::path model = fleet.dir / "fleet_model.json";
  std::ofstream(model, std::ios::binary)
      << host::calibration_json(calibration, "flange simulate --scenario fleet").dump(1) << "\n";
  fleet.chain.calibration = model.string();
  std::vector<host::BenchRow> rows;
  host::RecordingReader reader(bench_csv.string());
  while (const std::optional<host::RecordingRow> row = reader.next()) {
    rows.push_back({row->t_s, row->clearance_mm, row->temp_c, row->voltage_v});
  }
  host::SessionRecord session;
  session.kind = host::SessionKind::kBench;
  session.label = "fleet depot bench";
  session.started_at = utc_at(fleet.truth.settings.start_day, 0.0);
  session.sample_rate_hz = fleet.recording.fs_hz;
  session.source_file = bench_csv.string();
  session.source_sha256 = host::file_sha256(bench_csv.string());
  host::CalibrationRecord record;
  record.fitted_at = session.started_at;
  std::ifstream model_in(model);
  record.model_json.assign(std::istreambuf_iterator<char>(model_in), {});
  record.rows = calibration.rows;
  record.rmse_mm = calibration.fit.stats.rmse_mm;
  record.session_ids.push_back(fleet.store->record_session(session, rows));
  fleet.calibration_id = fleet.store->record_calibration(record);
}

// The fleet's locomotives, wheels and sensors (one sensor per wheel, named by both).
void register_fleet(Fleet& fleet) {
  const std::vector<host::LocomotiveRecord> stored = fleet.store->locomotives();
  for (const sim::LocomotiveTruth& loco : fleet.truth.locomotives) {
    for (const host::LocomotiveRecord& record : stored) {
      if (record.name == loco.name) {
        throw BadArgument(
            fmt::format("--store {}: already holds locomotive {}; simulate a fleet "
                        "into a new store",
                        fleet.store->name(), loco.name));
      }
    }
  }
  for (const sim::LocomotiveTruth& loco : fleet.truth.locomotives) {
    fleet.store->upsert_locomotive(
        {loco.name, fmt::format("fleet scenario, seed {}", fleet.truth.settings.seed)});
    for (int channel = 0; channel < sim::kMaxWheels; ++channel) {
      fleet.store->upsert_wheel({wheel_key(loco.name, channel), channel});
      host::SensorRecord sensor;
      sensor.serial = fmt::format("{}-S{:02d}", loco.name, channel);
      sensor.model = "inductive, twin of thesis eq. 3.14";
      sensor.fitted_to = wheel_key(loco.name, channel);
      sensor.fitted_at = utc_at(fleet.truth.settings.start_day, 0.0);
      fleet.store->upsert_sensor(sensor);
    }
  }
}

// The manifest of the day's twelve recordings, as `flange simulate --wheels 12` writes it.
host::LocomotiveManifest day_manifest(const Fleet& fleet) {
  std::vector<host::ManifestChannel> channels;
  for (int channel = 0; channel < sim::kMaxWheels; ++channel) {
    const sim::WheelPosition position = sim::wheel_position(channel);
    host::ManifestChannel entry;
    entry.channel = channel;
    entry.axle = position.axle;
    entry.side = position.side == sim::WheelSide::kLeft ? host::ManifestSide::kLeft
                                                        : host::ManifestSide::kRight;
    entry.file = host::channel_file_name(channel);
    channels.push_back(entry);
  }
  const fs::path path = fleet.days_dir / "locomotive.json";
  host::write_locomotive_manifest(path, channels, "flange simulate --scenario fleet");
  return host::load_locomotive_manifest(path.string());
}

std::string read_text(const fs::path& path) {
  std::ifstream file(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(file), {}};
}

// One locomotive's day: its recordings through the chain into the store as one run.
void run_day(Fleet& fleet, int locomotive, int day, double odometer_km) {
  const sim::LocomotiveTruth& loco = fleet.truth.locomotives[static_cast<std::size_t>(locomotive)];
  sim::simulate_fleet_day(fleet.truth, locomotive, day, fleet.recording, fleet.twin,
                          fleet.days_dir);
  const host::LocomotiveRun run =
      host::run_locomotive(day_manifest(fleet), fleet.chain, std::nullopt, true);
  const std::string started_at = utc_at(fleet.truth.settings.start_day + day, kServiceStartHours);
  host::write_locomotive_summary_json(fleet.days_dir / "summary.json", run,
                                      "flange simulate --scenario fleet");
  // Each wheel's clearance at reference conditions and, the new flange's gap being known, its
  // wear; alarm events and the reduced trace, as `flange run --manifest --store` keeps them.
  const double distance_km = fleet.recording.duration_s * sim::LocoRun{}.track.speed_mps / 1000.0;
  host::RunRecord record =
      locomotive_run_record(run, loco.name, distance_km, fleet.chain.thresholds.sensor_gap_mm);
  record.started_at = started_at;
  record.odometer_km = odometer_km + record.distance_km;
  record.coefficient_set = fleet.chain.coeffs;
  record.calibration_id = fleet.calibration_id;
  record.engine = fleet.chain.engine;
  record.sample_rate_hz = fleet.recording.fs_hz;
  record.summary_json = read_text(fleet.days_dir / "summary.json");
  // The day's session: its twelve recordings, named by the manifest and hashed together (the
  // files are deleted once stored), written in the run's own transaction.
  host::SessionRecord session;
  session.label = fmt::format("{} {}", loco.name, started_at);
  session.started_at = started_at;
  session.sample_rate_hz = fleet.recording.fs_hz;
  session.source_file = (fleet.days_dir / "locomotive.json").string();
  std::string hashes;
  for (const host::ChannelRun& channel : run.channels) {
    hashes += host::file_sha256(channel.channel.path.string());
  }
  session.source_sha256 = host::text_sha256(hashes);
  record.session = session;
  record.coefficient_sha256 = host::file_sha256(fleet.chain.coeffs);
  fleet.store->record_run(record);
}

// The depot's reprofilings of `day` as maintenance events; how many wheels.
int record_reprofilings(Fleet& fleet, int locomotive, int day, double odometer_km) {
  const sim::LocomotiveTruth& loco = fleet.truth.locomotives[static_cast<std::size_t>(locomotive)];
  int wheels = 0;
  for (const sim::WheelTruth& wheel : loco.wheels) {
    for (const int reprofiled : wheel.reprofiled_days) {
      if (reprofiled != day) continue;
      host::MaintenanceRecord event;
      event.wheel = wheel_key(loco.name, wheel.channel);
      event.at = utc_at(fleet.truth.settings.start_day + day, kMaintenanceHours);
      event.odometer_km = odometer_km;
      event.kind = "reprofile";
      event.note = "wheel lathe: a new flange profile";
      fleet.store->record_maintenance(event);
      ++wheels;
    }
  }
  return wheels;
}

Fleet set_up_fleet(const SimulateOptions& options) {
  refuse_loco_options(options);
  sim::FleetSettings settings;
  settings.locomotives = required(options.locomotives, "--locomotives", sim::kMaxFleetLocomotives);
  settings.days = required(options.days, "--days", sim::kMaxFleetDays);
  settings.seed = options.seed.value_or(0);
  if (!options.store) {
    throw BadArgument("--store is required with --scenario fleet: sqlite:PATH or postgresql://...");
  }
  host::StoreUrl url;
  naming_option("--store", [&] { url = host::parse_store_url(*options.store); });
  Fleet fleet;
  fleet.truth = sim::plan_fleet(settings);
  fleet.twin = sim::twin_with_effects(options.twin, std::nullopt, options.effects);
  fleet.dir = fleet_folder(options, url);
  fleet.days_dir = fleet.dir / "fleet_day";
  fleet.chain.coeffs = (runtime::data_dir().root / "coeffs/measurement_sos/filter.json").string();
  fleet.chain.engine = "model";
  fleet.chain.threads = 1;
  fs::create_directories(fleet.days_dir);
  fleet.store = host::open_store(*options.store);
  return fleet;
}

void print_truth(const Fleet& fleet, int runs, int reprofiled_wheels, const fs::path& truth,
                 std::ostream& out) {
  out << fmt::format("  {} runs of 12 wheels through the chain into {}; {} wheels reprofiled\n",
                     runs, fleet.store->name(), reprofiled_wheels);
  for (const sim::SensorDrift& drift : fleet.truth.drifts) {
    const sim::WheelPosition position = sim::wheel_position(drift.channel);
    out << fmt::format("  drifting sensor: {} axle {} {} from {} at {:+.4f} V/day\n",
                       fleet.truth.locomotives[static_cast<std::size_t>(drift.locomotive)].name,
                       position.axle, sim::side_name(position.side),
                       sim::iso_date(fleet.truth.settings.start_day + drift.start_day),
                       drift.rate_v_per_day);
  }
  out << "  wrote the truth to " << truth.string() << "\n";
}

}  // namespace

int run_fleet_simulation(const SimulateOptions& options,
                         const std::vector<std::string>& command_line, std::ostream& out) {
  Fleet fleet = set_up_fleet(options);
  const sim::FleetSettings& settings = fleet.truth.settings;
  out << fmt::format(
      "simulate: fleet scenario, {} locomotives x {} days from {}, seed {}; each running day "
      "{} s of 12 wheels at {} Hz\n",
      settings.locomotives, settings.days, sim::iso_date(settings.start_day), settings.seed,
      fleet.recording.duration_s, fleet.recording.fs_hz);
  if (options.save_twin) sim::save_twin(fleet.twin, *options.save_twin);
  register_fleet(fleet);
  calibrate_depot(fleet, settings.seed);
  std::vector<double> odometer_km(fleet.truth.locomotives.size(), 0.0);
  int runs = 0, reprofiled = 0;
  for (int day = 0; day < settings.days; ++day) {
    for (int l = 0; l < settings.locomotives; ++l) {
      const double km = fleet.truth.locomotives[static_cast<std::size_t>(l)]
                            .day_km[static_cast<std::size_t>(day)];
      reprofiled += record_reprofilings(fleet, l, day, odometer_km[static_cast<std::size_t>(l)]);
      if (km > 0.0) {
        run_day(fleet, l, day, odometer_km[static_cast<std::size_t>(l)]);
        ++runs;
      }
      odometer_km[static_cast<std::size_t>(l)] += km;
    }
  }
  const fs::path truth = fleet.dir / "fleet_truth.json";
  sim::write_fleet_truth(truth, fleet.truth, fleet.recording, runtime::generated_by(command_line));
  fs::remove_all(fleet.days_dir);
  print_truth(fleet, runs, reprofiled, truth, out);
  return kExitOk;
}

}  // namespace flange::cli
