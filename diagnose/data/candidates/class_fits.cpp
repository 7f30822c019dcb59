// SPDX-License-Identifier: MIT
#include "class_fits.h"

#include <fmt/format.h>

#include "effect_classes.h"
#include "effect_fit.h"
#include "family_makers.h"
#include "lag_family.h"

namespace flange::diagnose {
namespace {

namespace fs = free_shapes;

// A periodic curve of the clearance is not weighed on a converter grid: the grid's quantisation
// error repeats with every LSB of voltage, which the sensor's sensitivity makes a ripple of about
// LSB / (dV/dd) in the clearance.
std::vector<FreeShapeFamily> nonlinearity_families() {
  return {{"nonlinearity", "V", fs::make_voltage_curve},
          {"nonlinearity", "d", fs::make_clearance_curve, /*weighed_on_a_converter_grid=*/true,
           /*over_the_top_also_of=*/"range_compression"},
          {"nonlinearity", "d, periodic", fs::make_clearance_ripple,
           /*weighed_on_a_converter_grid=*/false}};
}

// The law the free shape found, as the effect's drift; the free shape's voltage is sampled late
// or early, the effect's makes the temperature late where the skew turns positive, so only a law
// that keeps the voltage late all session is the effect.
std::optional<ShapeMember> skew_member(const FreeShapeFit& shape) {
  const auto& p = shape.params;
  if (p.count("skew_s_most") == 0 || p.at("skew_s_most") > 0.0) return std::nullopt;
  return ShapeMember{"channel_skew",
                     {{"skew_s", p.at("skew_s_at_start")},
                      {"drift_s_per_h", p.at("drift_s_per_h")},
                      {"drift_change_s_per_h2", p.at("drift_change_s_per_h2")}}};
}

// A lag's free shape as the twin's lag. The coil's mix (LagFamily) by its mean delay: thermal_lag
// at tau_s. The mix in volts (VoltsLagFamily, whose summary has v_per_c): thermal_lag_volts, A
// (S T - T) with the family's lags as its paths, each weight the shape's over the weights' sum
// (so that they sum to 1) and A = v_per_c, the scale times that sum: the same voltage. Nothing
// where the weights sum to 0 (no amplitude to scale them by) or leave the effect's ranges.
std::optional<ShapeMember> lag_member(const FreeShapeFit& shape) {
  const auto& p = shape.params;
  if (p.count("v_per_c") == 0) {
    if (p.count("tau_s") == 0) return std::nullopt;
    return ShapeMember{"thermal_lag", {{"tau_s", p.at("tau_s")}}};
  }
  const auto& lags = fs::LagFamily::kLags;
  double sum = 0.0;
  for (const double tau : lags) sum += p.at(fs::LagFamily::lag_weight_name(tau));
  if (sum == 0.0) return std::nullopt;
  ShapeMember member{"thermal_lag_volts", {{"v_per_c", p.at("v_per_c")}}};
  for (std::size_t k = 0; k < lags.size(); ++k) {
    member.params[fmt::format("tau_{}_s", k + 1)] = lags[k];
    member.params[fmt::format("weight_{}", k + 1)] =
        p.at(fs::LagFamily::lag_weight_name(lags[k])) / sum;
  }
  return member;
}

const std::vector<ClassFit>& class_fits() {
  static const std::vector<ClassFit> fits = {
      {"temp_gain_drift", fit_by_search,
       {{"temp_gain_drift", "(V - v_min) T", fs::make_temperature_gain_curve,
         /*weighed_on_a_converter_grid=*/true, /*over_the_top_also_of=*/"",
         /*temperature_alone_also_of=*/"temp_offset_drift"},
        {"temp_gain_drift", "(V - pivot) T", fs::make_pivot_gain,
         /*weighed_on_a_converter_grid=*/true, /*over_the_top_also_of=*/"",
         /*temperature_alone_also_of=*/"temp_offset_drift"}}},
      {"temp_offset_drift", fit_by_search,
       {{"temp_offset_drift", "T", fs::make_temperature_offset_curve}}},
      {"nonlinearity", fit_by_search, nonlinearity_families()},
      {"range_compression", fit_by_search,
       {{"range_compression", "top of V, T", fs::make_compression_surface},
        {"range_compression", "V over a moving knee", fs::make_moving_knee}}},
      {"thermal_lag", fit_by_search,
       {{"thermal_lag", "lagged T", fs::make_lag},
        {"thermal_lag", "lagged T, in volts", fs::make_volts_lag}},
       lag_member},
      {"channel_skew", fit_by_search, {{"channel_skew", "t", fs::make_skew}}, skew_member},
      {"ageing_drift", fit_ageing,
       {{"ageing_drift", "age, continuing", fs::make_continuing_ageing},
        {"ageing_drift", "age, settled", fs::make_settled_age_curve},
        {"ageing_drift", "age, a level between sessions", fs::make_ageing_level}}},
      {"mains_pickup", fit_mains, {{"mains_pickup", "aliased lines", fs::make_mains_lines}}},
  };
  return fits;
}

}  // namespace

const ClassFit& class_fit(const std::string& name) {
  for (const ClassFit& f : class_fits()) {
    if (f.name == name) return f;
  }
  static const ClassFit none{};
  return none;
}

std::vector<std::string> classes_with_fits() {
  std::vector<std::string> names;
  for (const ClassFit& f : class_fits()) names.push_back(f.name);
  return names;
}

std::vector<FreeShapeFamily> all_free_shape_families() {
  std::vector<FreeShapeFamily> families;
  for (const EffectClass& c : effect_classes()) {
    const std::vector<FreeShapeFamily>& of = class_fit(c.name).families;
    families.insert(families.end(), of.begin(), of.end());
  }
  return families;
}

}  // namespace flange::diagnose
