// SPDX-License-Identifier: MIT
#include "wheel_wear_reference.h"

#include <fmt/format.h>

#include <map>
#include <optional>

#include "input_error.h"
#include "utc_time.h"

namespace flange::cli {
namespace {

double seconds(const std::string& utc) { return parse_utc_time(utc, "a stored time"); }

bool changes_flange_or_sensor(const std::string& kind) {
  return kind == "reprofile" || kind == "sensor_replaced" || kind == "wheelset_moved";
}

// The wheel's latest stored wear before `before_s`.
std::optional<double> last_wear_before(host::Store& store, const host::WheelKey& wheel,
                                       double before_s) {
  std::optional<double> wear;
  for (const host::WearPoint& point : store.wear_history(wheel)) {
    if (seconds(point.started_at) < before_s && point.wear_mm) wear = point.wear_mm;
  }
  return wear;
}

// The wear the wheel had when `event` happened, carried to its first run after it.
std::optional<double> wear_carried(host::Store& store, const host::StoredMaintenance& stored) {
  const host::MaintenanceRecord& event = stored.event;
  const double at_s = seconds(event.at);
  if (event.kind == "reprofile") return 0.0;
  if (event.kind == "sensor_replaced") return last_wear_before(store, event.wheel, at_s);
  if (!event.from_axle) return std::nullopt;
  return last_wear_before(store, {event.wheel.locomotive, *event.from_axle, event.wheel.side},
                          at_s);
}

// The clearance of the wheel's first run after `after_s` and before `run_s`, if any.
std::optional<double> first_clearance_after(host::Store& store, const host::WheelKey& wheel,
                                            double after_s, double run_s) {
  for (const host::WearPoint& point : store.wear_history(wheel)) {
    const double t = seconds(point.started_at);
    if (t > after_s && t < run_s && point.clearance_mm) return point.clearance_mm;
  }
  return std::nullopt;
}

}  // namespace

void fill_wheel_wear(host::Store& store, host::RunRecord& record, double new_flange_clearance_mm) {
  const double run_s = seconds(record.started_at);
  const std::vector<host::StoredMaintenance> events = store.maintenance_events(record.locomotive);
  for (host::WheelRunResult& wheel : record.wheels) {
    if (!wheel.clearance_mm) continue;
    const host::WheelKey key{record.locomotive, wheel.axle, wheel.side};
    const host::StoredMaintenance* latest = nullptr;
    for (const host::StoredMaintenance& stored : events) {
      if (stored.event.wheel == key && changes_flange_or_sensor(stored.event.kind) &&
          seconds(stored.event.at) < run_s) {
        latest = &stored;
      }
    }
    wheel.wear_mm = *wheel.clearance_mm - new_flange_clearance_mm;
    if (latest == nullptr) continue;
    const std::optional<double> carried = wear_carried(store, *latest);
    if (!carried) continue;
    const double reference = first_clearance_after(store, key, seconds(latest->event.at), run_s)
                                 .value_or(*wheel.clearance_mm);
    wheel.wear_mm = *carried + *wheel.clearance_mm - reference;
  }
}

double continuous_odometer(host::Store& store, const host::RunRecord& record, double reading_km) {
  const double run_s = seconds(record.started_at);
  std::map<std::string, double> resets;  // by time: recorded on every wheel, counted once
  for (const host::StoredMaintenance& stored : store.maintenance_events(record.locomotive)) {
    if (stored.event.kind == "odometer_reset" && seconds(stored.event.at) < run_s) {
      resets[stored.event.at] = stored.event.odometer_km;
    }
  }
  double odometer = reading_km;
  for (const auto& [at, before_km] : resets) odometer += before_km;
  if (record.wheels.empty()) return odometer;
  // One wheel's runs are the locomotive's.
  const host::WheelRunResult& wheel = record.wheels.front();
  std::optional<host::WearPoint> last;
  for (const host::WearPoint& point :
       store.wear_history({record.locomotive, wheel.axle, wheel.side})) {
    if (seconds(point.started_at) < run_s && (!last || point.odometer_km > last->odometer_km)) {
      last = point;
    }
  }
  if (last && odometer < last->odometer_km - 1e-6) {
    throw host::InputError(fmt::format(
        "--odometer-km {} ({} km over the recorded resets): below the {} km of locomotive {} at "
        "its run of {}; record the reset first (flange maintenance --kind odometer_reset "
        "--odometer-km READING_BEFORE_IT)",
        reading_km, odometer, last->odometer_km, record.locomotive, last->started_at));
  }
  return odometer;
}

}  // namespace flange::cli
