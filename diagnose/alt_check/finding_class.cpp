// SPDX-License-Identifier: MIT
#include "finding_class.h"

#include <map>

namespace flange::diagnose {
namespace {

double param_or_zero(const EffectFinding& f, const std::string& key) {
  const auto it = f.params.find(key);
  return it == f.params.end() ? 0.0 : it->second;
}

}  // namespace

std::string class_of_finding(const EffectFinding& finding) {
  static const std::map<std::string, std::string> kOneToOne = {
      {"temp_offset_drift", "temperature_offset"},
      {"temp_gain_drift", "temperature_gain"},
      {"nonlinearity", "static_nonlinearity"},
      {"range_compression", "range_compression"},
      {"ageing_drift", "ageing"},
      {"mains_pickup", "mains_pickup"},
      {"vibration", "mount_vibration"},
      {"adc_quantization", "quantisation"}};
  if (finding.name == "thermal_lag") {
    return param_or_zero(finding, "tau_s") >= 0.0 ? "sensor_thermal_lag"
                                                  : "temperature_reading_lag";
  }
  if (finding.name == "channel_skew") {
    return param_or_zero(finding, "skew_s") <= 0.0 ? "channel_skew" : "temperature_reading_lag";
  }
  const auto it = kOneToOne.find(finding.name);
  return it == kOneToOne.end() ? "" : it->second;
}

}  // namespace flange::diagnose
