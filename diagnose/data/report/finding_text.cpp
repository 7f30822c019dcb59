// SPDX-License-Identifier: MIT
#include "finding_text.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace flange::diagnose {
namespace {

bool is_undetermined(const EffectFinding& f, const std::string& key) {
  return std::find(f.undetermined.begin(), f.undetermined.end(), key) != f.undetermined.end();
}

std::string one_or_other(const EffectFinding& f) {
  if (f.indistinguishable_from.empty()) return f.name;
  std::string names = f.name;
  for (std::size_t k = 0; k < f.indistinguishable_from.size(); ++k) {
    names +=
        (k + 1 == f.indistinguishable_from.size() ? " or " : ", ") + f.indistinguishable_from[k];
  }
  return names + " (these data cannot tell them apart)";
}

}  // namespace

std::string params_text(const EffectFinding& f) {
  std::string text;
  for (const auto& [key, value] : f.params) {
    text += text.empty() ? "" : ",";
    if (is_undetermined(f, key)) {
      text += key + "=undetermined";
    } else if (auto bound = f.bounds.find(key); bound != f.bounds.end()) {
      text += key + bound->second.substr(0, 2) + bound->second.substr(3);
    } else {
      text += fmt::format("{}={:.4g}", key, value);
    }
  }
  if (f.level) {
    text += fmt::format(", at {:.1f} degC {}={:.4g}", f.level->temp_c, f.level->key,
                        f.level->value);
  }
  return text;
}

nlohmann::ordered_json level_json(const EffectFinding& f) {
  if (!f.level) return nullptr;
  const double r = f.level->resolution;
  return {{"temp_c", f.level->temp_c},
          {f.level->key, f.level->value},
          {"resolution", std::isfinite(r) ? nlohmann::ordered_json(r) : nlohmann::ordered_json()}};
}

nlohmann::ordered_json params_json(const EffectFinding& f) {
  nlohmann::ordered_json params = nlohmann::ordered_json::object();
  for (const auto& [key, value] : f.params) {
    if (is_undetermined(f, key)) {
      params[key] = nullptr;
    } else if (auto bound = f.bounds.find(key); bound != f.bounds.end()) {
      params[key] = bound->second;
    } else {
      params[key] = value;
    }
  }
  return params;
}

nlohmann::ordered_json resolution_json(const EffectFinding& f) {
  nlohmann::ordered_json out = nlohmann::ordered_json::object();
  for (const auto& [key, value] : f.resolution) {
    out[key] = std::isfinite(value) ? nlohmann::ordered_json(value) : nlohmann::ordered_json();
  }
  return out;
}

std::string verdict_names(const std::vector<EffectFinding>& findings) {
  std::string names;
  for (const EffectFinding& f : findings) names += (names.empty() ? "" : ", ") + one_or_other(f);
  return names;
}

}  // namespace flange::diagnose
