// SPDX-License-Identifier: MIT
// A small simulated fleet written into a new store on one backend, as the wear tests that run on
// both backends start: the test's folder, the store's URL and how `flange simulate` ended.
#pragma once

#include <unistd.h>

#include <filesystem>
#include <string>

#include "flange_in_process.h"
#include "store_test_backends.h"
#include "test_files.h"

namespace flange::testing {

struct SimulatedFleetStore {
  std::filesystem::path dir;
  std::string store;
  FlangeOutcome simulated;
};

// `flange simulate --scenario fleet` of `locomotives` x `days` at `seed` into a fresh store named
// after `test` and the backend, its files in a fresh folder of the same name.
inline SimulatedFleetStore simulate_fleet_into_store(const std::string& test,
                                                     StoreBackendUnderTest backend,
                                                     int locomotives, int days, int seed) {
  SimulatedFleetStore out;
  const std::string name = test + "_" + backend_test_name(backend);
  out.dir = fresh_test_dir(name + "_" + std::to_string(::getpid()));
  out.store = fresh_store_url(backend, name);
  out.simulated = run_flange_captured(
      {"simulate", "--scenario", "fleet", "--locomotives", std::to_string(locomotives), "--days",
       std::to_string(days), "--seed", std::to_string(seed), "--store", out.store, "--out",
       (out.dir / "fleet").string()});
  return out;
}

}  // namespace flange::testing
