// SPDX-License-Identifier: MIT
// Null replicas behind the stage floors: the noisy twin drawn criteria::kNullReplicas times at
// the estimated noise (on the recording's converter grid, if it has one).
#pragma once

#include <algorithm>
#include <cstdint>
#include <functional>
#include <vector>

#include "criteria.h"
#include "gaussian_source.h"
#include "measurement_chain.h"
#include "parallel_work.h"
#include "recording_series.h"
#include "white_noise.h"

namespace flange::diagnose {

// The noisy twin of one null replica, from the replica's standard normals `z` (one per sample)
// and a `seed` for what the twin draws itself; unset: the noiseless replay plus the white noise.
// Set when the twin holds mount motion, each session's own random motion: the twin is replayed
// without it, and each replica draws it afresh. Set when the twin holds the converter: its replay
// lies on the converter's codes, and a replica adds the analog noise before the rounding, as the
// converter sees it, or it would stay on the replay's codes.
using NullReplica =
    std::function<std::vector<double>(std::uint64_t seed, const std::vector<double>& z)>;

// Calls each(replica, noisy_v, d_noisy, f_noisy) for criteria::kNullReplicas draws of the noisy
// twin (on the recording's converter grid, if it has one) of `sim_v` (drawn by `replica_of`,
// when set), with its compensated and filtered clearance. The draws come from one stream in
// replica order, so the floors do not depend on the threads; what each draw then costs (motion,
// inversion, filter, alarms: most of it) runs as many replicas at a time as there are worker
// threads (parallel_work.h), so `each` must only write to its replica's own place.
template <class Each>
void for_each_null_replica(const RecordingSeries& real, const std::vector<double>& sim_v,
                           const WhiteNoise& white, const sim::PolynomialSensorModel& model,
                           double fs_hz, std::uint64_t seed, Each each,
                           const NullReplica& replica_of = {}) {
  // Replicas run a batch at a time, while the next batch's normals are drawn beside them: a
  // batch's normals and the next's are all that is held at once.
  const int batch = worker_threads();
  sim::GaussianSource noise(seed);
  const auto draw = [&](int count) {
    std::vector<std::vector<double>> zs(static_cast<std::size_t>(count));
    for (std::vector<double>& z : zs) {
      z.resize(sim_v.size());
      for (double& zi : z) zi = noise.standard_normal();
    }
    return zs;
  };
  std::vector<std::vector<double>> next = draw(std::min(batch, criteria::kNullReplicas));
  for (int first = 0; first < criteria::kNullReplicas; first += batch) {
    const std::vector<std::vector<double>> zs = std::move(next);
    const int count = static_cast<int>(zs.size());
    const int next_count = std::clamp(criteria::kNullReplicas - first - count, 0, batch);
    // Piece 0 draws the next batch; piece k > 0 runs replica first + k - 1.
    run_in_parallel(count + 1, 0, [&](int piece) {
      if (piece == 0) {
        next = draw(next_count);
        return;
      }
      const int replica = first + piece - 1;
      const std::vector<double>& z = zs[static_cast<std::size_t>(piece - 1)];
      std::vector<double> noisy_v(sim_v.size());
      if (replica_of) {
        noisy_v = replica_of(sim::derive_seed(seed, 1000 + static_cast<std::uint64_t>(replica)), z);
      } else {
        for (std::size_t i = 0; i < sim_v.size(); ++i) noisy_v[i] = white.noisy(sim_v[i], z[i]);
      }
      const std::vector<double> d_noisy = clearance_of(model, noisy_v, real.temp_c);
      each(static_cast<std::size_t>(replica), noisy_v, d_noisy, measurement_filter(d_noisy, fs_hz));
    });
  }
}

}  // namespace flange::diagnose
