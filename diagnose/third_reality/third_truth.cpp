// SPDX-License-Identifier: MIT
#include "third_truth.h"

#include <fmt/format.h>

#include <fstream>
#include <stdexcept>
#include <string>

#include "version.h"

namespace flange::third_reality {
namespace {

void write_recording(const std::filesystem::path& path, const ThirdRecording& r) {
  std::ofstream csv(path, std::ios::binary);
  csv << "t_s,clearance_mm,temp_c,voltage_v\n";
  for (std::size_t k = 0; k < r.size(); ++k) {
    csv << fmt::format("{:.6f},{:.6f},{:.6f},{:.6f}\n", r.t_s[k], r.clearance_mm[k], r.temp_c[k],
                       r.voltage_v[k]);
  }
  csv.close();
  if (!csv) throw std::runtime_error(path.string() + ": cannot write");
}

}  // namespace

nlohmann::json third_truth_json(const ThirdPairSpec& spec) {
  nlohmann::json truth = nlohmann::json::array();
  for (const ThirdTruthEffect& e : spec.truth) {
    truth.push_back({{"class", e.draw.class_name},
                     {"shape", e.draw.shape},
                     {"params", e.draw.params},
                     {"rms_v", e.rms_v},
                     {"rms_over_noise", e.rms_v / spec.fit.noise_v}});
  }
  return {{"generated_by", runtime::generated_by(fmt::format(
                               "flange diagnose --selftest --reality third --case {} --seed {}",
                               spec.index, spec.seed))},
          {"note", "the truth of a third-reality pair; never read by the diagnosis"},
          {"pair", spec.index},
          {"seed", spec.seed},
          {"kind", third_pair_kind_name(spec.kind)},
          {"truth", truth},
          {"fit_session", session_plan_json(spec.fit)},
          {"heldout_session", session_plan_json(spec.heldout)}};
}

std::vector<std::filesystem::path> write_third_pair(const std::filesystem::path& dir,
                                                    const ThirdPairSpec& spec,
                                                    const ThirdPair& pair) {
  const auto name = [&](const char* what) {
    return dir / fmt::format("pair_{}_{}", spec.index, what);
  };
  const std::vector<std::filesystem::path> paths = {name("fit.csv"), name("heldout.csv"),
                                                    name("truth.json")};
  write_recording(paths[0], pair.fit);
  write_recording(paths[1], pair.heldout);
  std::ofstream json(paths[2], std::ios::binary);
  json << third_truth_json(spec).dump(2) << "\n";
  json.close();
  if (!json) throw std::runtime_error(paths[2].string() + ": cannot write");
  return paths;
}

}  // namespace flange::third_reality
