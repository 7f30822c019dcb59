// SPDX-License-Identifier: MIT
#include "claims_json.h"

namespace flange::diagnose {

nlohmann::json claims_json(const std::vector<EffectFinding>& effects,
                           const std::vector<std::string>& claimed,
                           const std::vector<bool>& right) {
  nlohmann::json claims = nlohmann::json::array();
  for (std::size_t k = 0; k < claimed.size() && k < effects.size() && k < right.size(); ++k) {
    claims.push_back(
        {{"class", claimed[k]}, {"confidence", effects[k].confidence}, {"right", right[k]}});
  }
  return claims;
}

}  // namespace flange::diagnose
