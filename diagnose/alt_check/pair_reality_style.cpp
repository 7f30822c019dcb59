// SPDX-License-Identifier: MIT
#include "pair_reality_style.h"

namespace flange::diagnose {

BlindStyle pair_reality_style(const std::string& reality, const std::string& truth_title,
                              const BlindAims& aims, const SelftestOptions& options) {
  BlindStyle style;
  style.noun = "pair";
  style.command = "flange diagnose --selftest --reality " + reality;
  style.item = "class";
  style.items = "classes";
  style.top_label = "right top class";
  style.named_title = "classes named";
  style.named_width = 34;
  style.truth_title = truth_title;
  style.claimed_key = "claimed_classes";
  style.shows_noise = true;
  style.shows_nearest = true;
  style.aims = aims;
  style.run_json = {{"reality", reality}, {"seed", options.seed}};
  return style;
}

}  // namespace flange::diagnose
