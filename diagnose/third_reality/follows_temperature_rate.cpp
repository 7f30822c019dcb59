// SPDX-License-Identifier: MIT
// Classes that follow the temperature's rate of change through a lag kernel of one to three
// paths: the sensor's own lag, V' = V + A (T - K*T) (what the coil has not yet caught up with,
// in volts), and a lagging temperature reading, T_read = K*T.
#include <memory>

#include "lag_kernel.h"
#include "third_classes.h"

namespace flange::third_reality {
namespace {

int paths_of(const std::string& shape) {
  return shape == "one_path" ? 1 : shape == "two_paths" ? 2 : 3;
}

class SensorLag : public ThirdEffect {
 public:
  explicit SensorLag(const EffectDraw& d)
      : kernel_(get_lag_kernel(d.params, "path")), volts_per_c_(d.params.at("amplitude_v_per_c")) {}
  void sense(const ChannelPass& pass, std::vector<double>& v) const override {
    const HeatingPlan& heating = pass.plan->heating;
    const std::vector<double> lagged = apply_lag_kernel(
        kernel_, [&](double t) { return heating(t); }, pass.instant_s);
    for (std::size_t k = 0; k < v.size(); ++k) {
      v[k] += volts_per_c_ * (pass.ambient_c[k] - lagged[k]);
    }
  }

 private:
  LagKernel kernel_;
  double volts_per_c_;
};

class ReadingLag : public ThirdEffect {
 public:
  explicit ReadingLag(const EffectDraw& d) : kernel_(get_lag_kernel(d.params, "path")) {}
  void read_temperature(const ChannelPass& pass, std::vector<double>& temp_c) const override {
    const HeatingPlan& heating = pass.plan->heating;
    temp_c = apply_lag_kernel(
        kernel_, [&](double t) { return heating(t); }, pass.instant_s);
  }

 private:
  LagKernel kernel_;
};

}  // namespace

ThirdClass sensor_thermal_lag_class() {
  ThirdClass c;
  c.name = "sensor_thermal_lag";
  c.shapes = {"one_path", "two_paths", "three_paths"};
  c.draw = [](const std::string& shape, const DrawContext&, ThirdRandom& random) {
    EffectDraw d{"sensor_thermal_lag", shape, {}, "amplitude_v_per_c"};
    put_lag_kernel(draw_lag_kernel(paths_of(shape), 60.0, 1500.0, 120.0, random), "path", d.params);
    d.params["amplitude_v_per_c"] = random.sign() * 0.005;
    return d;
  };
  c.make = [](const EffectDraw& d, const SessionPlan&) -> std::unique_ptr<ThirdEffect> {
    return std::make_unique<SensorLag>(d);
  };
  return c;
}

ThirdClass temperature_reading_lag_class() {
  ThirdClass c;
  c.name = "temperature_reading_lag";
  c.shapes = {"one_path", "two_paths", "three_paths"};
  c.sets_noise = true;
  c.draw = [](const std::string& shape, const DrawContext&, ThirdRandom& random) {
    EffectDraw d{"temperature_reading_lag", shape, {}, ""};
    put_lag_kernel(draw_lag_kernel(paths_of(shape), 30.0, 900.0, 90.0, random), "path", d.params);
    return d;
  };
  c.make = [](const EffectDraw& d, const SessionPlan&) -> std::unique_ptr<ThirdEffect> {
    return std::make_unique<ReadingLag>(d);
  };
  return c;
}

}  // namespace flange::third_reality
