// SPDX-License-Identifier: MIT
#include "fleet_alt_plan.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "fleet_alt_limits.h"

namespace flange::fleet_alt {
namespace {

// Streams of the seed: one per purpose, far apart.
constexpr std::uint64_t kRouteStream = 100, kWeatherStream = 200, kEventStream = 300;
constexpr std::uint64_t kLocomotiveStream = 1000;  // + locomotive

constexpr double kDepotChance = 0.12;        // a locomotive stands in the depot that day
constexpr double kMissingChance = 0.05;      // it ran but its recorder kept nothing
constexpr double kRouteChangeChance = 0.35;  // its roster changes route at a week's start
constexpr double kLatheLimitMm = 4.6;        // the depot turns an axle whose worse flange passed it
constexpr double kLatheResidueMm = 0.15;     // a lathe pass leaves up to this much of the old wear
constexpr std::array<double, 6> kAxleWearShare = {1.3, 0.75, 1.0, 1.3, 0.75, 1.0};

struct Wheelset {
  std::array<double, 2> wear_mm{};  // left, right
  std::array<double, 2> base{};     // mm per 1000 km
};

// A locomotive's state as the days pass.
struct LocoState {
  double odometer_km = 0.0;
  int route = 0;
  std::array<Wheelset, 6> wheelsets;
  std::array<int, 6> at_axle{0, 1, 2, 3, 4, 5};  // wheelset on each axle
  std::array<WheelOnDay, kWheels> sensors;
  std::array<int, kWheels> units_fitted{};
};

DepotEvent event_at(int day, int locomotive, DepotEventKind kind, int axle = 0) {
  DepotEvent event;
  event.day = day;
  event.locomotive = locomotive;
  event.kind = kind;
  event.axle = axle;
  return event;
}

SensorUnit draw_unit(FleetRandom& random) {
  SensorUnit unit;
  unit.gain = 1.0 + 0.008 * random.normal();
  unit.zero_mm = 0.05 * random.normal();
  unit.offset_v = 0.03 * random.normal();
  return unit;
}

void fit_sensor(LocoState& state, const std::string& loco, int channel, FleetRandom& random) {
  WheelOnDay& wheel = state.sensors[static_cast<std::size_t>(channel)];
  const int n = ++state.units_fitted[static_cast<std::size_t>(channel)];
  wheel.unit = draw_unit(random);
  wheel.mount_mm = 0.12 * random.normal();
  wheel.serial = fmt::format("{}-S{:02d}-{}", loco, channel, n);
  wheel.coil_offset_c = 1.2 * random.normal();
}

LocoState initial_state(const std::string& name, FleetRandom& random) {
  LocoState state;
  state.odometer_km = random.uniform(150000.0, 900000.0);
  state.route = random.index(static_cast<int>(route_kinds().size()));
  for (Wheelset& set : state.wheelsets) {
    for (int s = 0; s < 2; ++s) {
      set.wear_mm[static_cast<std::size_t>(s)] = random.uniform(0.3, 4.2);
      set.base[static_cast<std::size_t>(s)] = 0.055 * std::exp(0.3 * random.normal());
    }
  }
  for (int c = 0; c < kWheels; ++c) fit_sensor(state, name, c, random);
  return state;
}

// Ambient (degC) on each of `count` days from day 0: two annual harmonics of its own and weather
// that persists (one stream: a longer count leaves the first days as they were).
std::vector<double> draw_ambient(const FleetAltSettings& settings, int count) {
  FleetRandom random(settings.seed, kWeatherStream);
  using namespace std::chrono;
  const year_month_day date{sys_days{days{settings.start_day}}};
  const auto first_doy =
      static_cast<double>((sys_days{date} - sys_days{date.year() / January / 1}).count());
  std::vector<double> ambient;
  double weather = 0.0;
  const double w = 2.0 * std::numbers::pi / 365.25;
  for (int d = 0; d < count; ++d) {
    const double doy = first_doy + d;
    weather = 0.75 * weather + 1.7 * random.normal();
    ambient.push_back(21.0 + 8.5 * std::cos(w * (doy - 196.0)) +
                      2.5 * std::cos(2.0 * w * (doy - 20.0)) + weather);
  }
  return ambient;
}

}  // namespace

double wear_rate_mm_per_1000km(const RouteKind& route, int axle, int side, double base,
                               double wear_mm, double ambient_c) {
  const double hand = side == 0 ? route.right_hand_share : 1.0 - route.right_hand_share;
  const double mid_radius = 0.5 * (route.radius_low_m + route.radius_high_m);
  const double route_factor = 0.45 + 2.2 * route.curve_share * hand * 600.0 / mid_radius;
  return base * kAxleWearShare.at(static_cast<std::size_t>(axle - 1)) * route_factor *
         (1.0 + 0.015 * (ambient_c - 22.0)) * std::exp(0.06 * wear_mm);
}

namespace {

// The depot's scheduled events (one of each kind) and the drifting sensor, for the fleet.
void schedule_events(FleetAltTruth& truth) {
  const FleetAltSettings& s = truth.settings;
  FleetRandom random(s.seed, kEventStream);
  const int last = s.locomotives - 1;
  const DepotEvent reset =
      event_at(static_cast<int>(std::lround(0.42 * s.days)), last, DepotEventKind::kOdometerReset);
  DepotEvent sensor =
      event_at(static_cast<int>(std::lround(0.5 * s.days)), 0, DepotEventKind::kSensorReplaced);
  const int channel = random.index(kWheels);
  sensor.axle = channel / 2 + 1;
  sensor.side = channel % 2;
  const int mover = std::min(2, last);
  const int first_axle = random.chance(0.5) ? 1 : 4;
  const int move_day = static_cast<int>(std::lround(0.62 * s.days));
  DepotEvent to_last = event_at(move_day, mover, DepotEventKind::kWheelsetMoved, first_axle + 2);
  to_last.from_axle = first_axle;
  DepotEvent to_first = event_at(move_day, mover, DepotEventKind::kWheelsetMoved, first_axle);
  to_first.from_axle = first_axle + 2;
  truth.events = {reset, sensor, to_last, to_first};
  DriftTruth& drift = truth.drift;
  drift.locomotive = s.locomotives > 1 ? 1 : 0;
  do {
    drift.channel = random.index(kWheels);
  } while (drift.locomotive == 0 && drift.channel == channel);
  drift.start_day = static_cast<int>(std::lround(0.3 * s.days));
  drift.rate_v_per_day = random.sign() * random.uniform(0.010, 0.025);
}

bool scheduled_on(const FleetAltTruth& truth, int locomotive, int day) {
  for (const DepotEvent& event : truth.events) {
    if (event.locomotive == locomotive && event.day == day) return true;
  }
  return false;
}

// The scheduled events of this locomotive's depot day, carried out.
void carry_out_scheduled(FleetAltTruth& truth, int l, int day, LocoState& state,
                         FleetRandom& random, std::vector<DepotEvent>& done) {
  const std::string& name = truth.locomotives[static_cast<std::size_t>(l)].name;
  for (const DepotEvent& planned : truth.events) {
    if (planned.locomotive != l || planned.day != day) continue;
    DepotEvent event = planned;
    event.odometer_reading_km = state.odometer_km;
    if (event.kind == DepotEventKind::kOdometerReset) state.odometer_km = 0.0;
    if (event.kind == DepotEventKind::kSensorReplaced) {
      const int channel = 2 * (event.axle - 1) + event.side;
      fit_sensor(state, name, channel, random);
      event.sensor_serial = state.sensors[static_cast<std::size_t>(channel)].serial;
    }
    if (event.kind == DepotEventKind::kWheelsetMoved && event.axle > event.from_axle) {
      std::swap(state.at_axle[static_cast<std::size_t>(event.axle - 1)],
                state.at_axle[static_cast<std::size_t>(event.from_axle - 1)]);
    }
    done.push_back(event);
  }
}

// The depot's lathe: every axle whose worse flange passed the limit is turned.
void lathe_passes(FleetAltTruth& truth, int l, int day, LocoState& state, FleetRandom& random,
                  std::vector<DepotEvent>& done) {
  LocomotiveHistory& loco = truth.locomotives[static_cast<std::size_t>(l)];
  for (int axle = 1; axle <= 6; ++axle) {
    Wheelset& set = state.wheelsets[static_cast<std::size_t>(state.at_axle[axle - 1])];
    if (std::max(set.wear_mm[0], set.wear_mm[1]) < kLatheLimitMm) continue;
    for (int s = 0; s < 2; ++s) {
      set.wear_mm[static_cast<std::size_t>(s)] = random.uniform(0.0, kLatheResidueMm);
      loco.positions[static_cast<std::size_t>(2 * (axle - 1) + s)].reprofiled_days.push_back(day);
    }
    DepotEvent event = event_at(day, l, DepotEventKind::kReprofile, axle);
    event.odometer_reading_km = state.odometer_km;
    done.push_back(event);
  }
}

LocomotiveDay day_record(int day, const LocoState& state) {
  LocomotiveDay record;
  record.day = day;
  record.route = state.route;
  record.odometer_reading_km = state.odometer_km;
  for (int c = 0; c < kWheels; ++c) {
    WheelOnDay wheel = state.sensors[static_cast<std::size_t>(c)];
    const Wheelset& set = state.wheelsets[static_cast<std::size_t>(state.at_axle[c / 2])];
    wheel.wear_mm = set.wear_mm[static_cast<std::size_t>(c % 2)];
    record.wheels[static_cast<std::size_t>(c)] = wheel;
  }
  return record;
}

// One day of locomotive l's wheels: each flange's wear over the day's km.
void wear_day(FleetAltTruth& truth, int l, int day, double km, LocoState& state) {
  LocomotiveHistory& loco = truth.locomotives[static_cast<std::size_t>(l)];
  const RouteKind& route = truth.routes[static_cast<std::size_t>(state.route)].kind;
  const double ambient = truth.ambient_c[static_cast<std::size_t>(day)];
  for (int c = 0; c < kWheels; ++c) {
    const int axle = c / 2 + 1, side = c % 2;
    Wheelset& set = state.wheelsets[static_cast<std::size_t>(state.at_axle[c / 2])];
    double& wear = set.wear_mm[static_cast<std::size_t>(side)];
    const double base = set.base[static_cast<std::size_t>(side)];
    const double gained =
        wear_rate_mm_per_1000km(route, axle, side, base, wear, ambient) * km / 1000.0;
    wear += gained;
    loco.positions[static_cast<std::size_t>(c)].accrued_mm.push_back(gained);
    loco.positions[static_cast<std::size_t>(c)].base_rate.push_back(base);
  }
}

// Locomotive l over every day.
void run_locomotive(FleetAltTruth& truth, int l, std::vector<DepotEvent>& done) {
  const FleetAltSettings& s = truth.settings;
  LocomotiveHistory& loco = truth.locomotives[static_cast<std::size_t>(l)];
  FleetRandom random(s.seed, kLocomotiveStream + static_cast<std::uint64_t>(l));
  LocoState state = initial_state(loco.name, random);
  if (truth.drift.locomotive == l) {
    SensorUnit& unit = state.sensors[static_cast<std::size_t>(truth.drift.channel)].unit;
    unit.drift_v_per_day = truth.drift.rate_v_per_day;
    unit.drift_start_day = truth.drift.start_day;
  }
  for (int c = 0; c < kWheels; ++c) {
    loco.positions[static_cast<std::size_t>(c)].initial_wear_mm =
        state.wheelsets[static_cast<std::size_t>(state.at_axle[c / 2])].wear_mm[c % 2];
  }
  const int routes = static_cast<int>(truth.routes.size());
  for (int day = 0; day < s.days; ++day) {
    if (day % 7 == 0 && day > 0 && random.chance(kRouteChangeChance)) {
      state.route = (state.route + 1 + random.index(routes - 1)) % routes;
    }
    const bool depot = day > 0 && (scheduled_on(truth, l, day) || random.chance(kDepotChance));
    if (depot) {
      carry_out_scheduled(truth, l, day, state, random, done);
      lathe_passes(truth, l, day, state, random, done);
    }
    LocomotiveDay record = day_record(day, state);
    const RouteKind& route = truth.routes[static_cast<std::size_t>(state.route)].kind;
    record.km = depot ? 0.0 : random.uniform(route.day_km_low, route.day_km_high);
    record.recorded = !depot && (day == 0 || !random.chance(kMissingChance));
    record.start_hour = random.uniform(5.0, 9.0);
    record.track_start_m =
        random.uniform(0.0, truth.routes[static_cast<std::size_t>(state.route)].length_m);
    record.parked_rise_c = random.uniform(1.0, 6.0);
    loco.days.push_back(record);
    wear_day(truth, l, day, record.km, state);
    state.odometer_km += record.km;
  }
  // After the period, from the same stream (the recorded days' draws stay as they were): the
  // roster's route changes and the depot days, and nothing else.
  for (int day = s.days; day < kTruthHorizonDays; ++day) {
    if (day % 7 == 0 && random.chance(kRouteChangeChance)) {
      state.route = (state.route + 1 + random.index(routes - 1)) % routes;
    }
    const RouteKind& route = truth.routes[static_cast<std::size_t>(state.route)].kind;
    const bool depot = random.chance(kDepotChance);
    loco.days_after.push_back(
        {state.route, depot ? 0.0 : random.uniform(route.day_km_low, route.day_km_high)});
  }
}

void check_settings(const FleetAltSettings& s) {
  if (s.locomotives < 1 || s.locomotives > kMaxLocomotives) {
    throw std::invalid_argument(
        fmt::format("--locomotives {}: a whole number 1 to {}", s.locomotives, kMaxLocomotives));
  }
  if (s.days < kMinDays || s.days > kMaxDays) {
    throw std::invalid_argument(
        fmt::format("--days {}: a whole number {} to {} (the depot's events need room)", s.days,
                    kMinDays, kMaxDays));
  }
  if (!(s.recording_s >= 60.0 && s.recording_s <= 3600.0)) {
    throw std::invalid_argument(fmt::format("--duration {}: 60 to 3600 s", s.recording_s));
  }
  if (!(s.fs_hz >= 1.0 && s.fs_hz <= 100.0)) {
    throw std::invalid_argument(fmt::format("--fs {}: 1 to 100 Hz", s.fs_hz));
  }
}

}  // namespace

const char* depot_event_name(DepotEventKind kind) {
  switch (kind) {
    case DepotEventKind::kReprofile:
      return "reprofile";
    case DepotEventKind::kSensorReplaced:
      return "sensor_replaced";
    case DepotEventKind::kWheelsetMoved:
      return "wheelset_moved";
    case DepotEventKind::kOdometerReset:
      return "odometer_reset";
  }
  return "";
}

FleetAltTruth plan_fleet_alt(const FleetAltSettings& settings) {
  check_settings(settings);
  FleetAltTruth truth;
  truth.settings = settings;
  FleetRandom route_random(settings.seed, kRouteStream);
  for (const RouteKind& kind : route_kinds()) {
    truth.routes.push_back(draw_route_track(kind, route_random));
  }
  truth.ambient_c = draw_ambient(settings, kTruthHorizonDays);
  truth.ambient_after_c.assign(truth.ambient_c.begin() + settings.days, truth.ambient_c.end());
  truth.ambient_c.resize(static_cast<std::size_t>(settings.days));
  for (int l = 0; l < settings.locomotives; ++l) {
    truth.locomotives.push_back({fmt::format("A{:02d}", l + 1), {}, {}, {}});
  }
  schedule_events(truth);
  std::vector<DepotEvent> done;
  for (int l = 0; l < settings.locomotives; ++l) run_locomotive(truth, l, done);
  std::stable_sort(done.begin(), done.end(), [](const DepotEvent& a, const DepotEvent& b) {
    return a.day != b.day ? a.day < b.day : a.locomotive < b.locomotive;
  });
  truth.events = std::move(done);
  date_limits(truth);
  return truth;
}

double position_rate_mm_per_1000km(const LocomotiveHistory& loco, int channel) {
  int first = -1, last = -1;
  for (const LocomotiveDay& day : loco.days) {
    if (!day.recorded) continue;
    if (first < 0) first = day.day;
    last = day.day;
  }
  const PositionTruth& position = loco.positions.at(static_cast<std::size_t>(channel));
  double wear = 0.0, km = 0.0;
  for (int d = std::max(first, 0); d < last; ++d) {
    wear += position.accrued_mm[static_cast<std::size_t>(d)];
    km += loco.days[static_cast<std::size_t>(d)].km;
  }
  return km > 0.0 ? 1000.0 * wear / km : 0.0;
}

std::string date_text(int day) {
  using namespace std::chrono;
  const year_month_day date{sys_days{days{day}}};
  return fmt::format("{:04d}-{:02d}-{:02d}", static_cast<int>(date.year()),
                     static_cast<unsigned>(date.month()), static_cast<unsigned>(date.day()));
}

}  // namespace flange::fleet_alt
