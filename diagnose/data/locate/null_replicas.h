// SPDX-License-Identifier: MIT
// Null replicas behind the stage floors: the noisy twin drawn criteria::kNullReplicas times at
// the estimated noise (on the recording's converter grid, if it has one).
#pragma once

#include <cstdint>
#include <future>
#include <vector>

#include "criteria.h"
#include "gaussian_source.h"
#include "measurement_chain.h"
#include "recording_series.h"
#include "white_noise.h"

namespace flange::diagnose {

// Calls each(replica, noisy_v, d_noisy, f_noisy) for criteria::kNullReplicas draws of the noisy twin (on
// the recording's converter grid, if it has one) of `sim_v`, with its compensated and filtered
// clearance. The draws come from one stream in replica order, so the floors do not depend on the
// threads; what each draw then costs (inversion, filter, alarms: most of it) runs two replicas at
// a time, so `each` must only write to its replica's own place.
template <class Each>
void for_each_null_replica(const RecordingSeries& real, const std::vector<double>& sim_v,
                           const WhiteNoise& white, const sim::PolynomialSensorModel& model,
                           double fs_hz, std::uint64_t seed, Each each) {
  constexpr std::size_t kInFlight = 2;
  sim::GaussianSource noise(seed);
  std::vector<std::future<void>> running;
  for (int replica = 0; replica < criteria::kNullReplicas; ++replica) {
    std::vector<double> noisy_v(sim_v.size());
    for (std::size_t i = 0; i < sim_v.size(); ++i) {
      noisy_v[i] = white.noisy(sim_v[i], noise.standard_normal());
    }
    if (running.size() == kInFlight) {
      running.front().get();
      running.erase(running.begin());
    }
    running.push_back(std::async(std::launch::async, [&, replica, noisy_v = std::move(noisy_v)] {
      const std::vector<double> d_noisy = clearance_of(model, noisy_v, real.temp_c);
      each(static_cast<std::size_t>(replica), noisy_v, d_noisy, measurement_filter(d_noisy, fs_hz));
    }));
  }
  for (std::future<void>& r : running) r.get();
}

}  // namespace flange::diagnose
