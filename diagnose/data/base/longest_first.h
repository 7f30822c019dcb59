// SPDX-License-Identifier: MIT
// Independent pieces of work claimed longest first. A round's pieces differ in length (a 100 Hz
// round's channel-skew candidate takes three times the others, and comes last in the class
// table); claimed in index order, the long one can start last and leave one core working alone
// at the end of the round while the other waits. Each kind of piece (a class's library
// candidate, a free-shape family) is timed when it runs, and a later map claims the kinds that
// took longest first. Only the order the pieces start in changes: each result is in its own slot
// (parallel_work.h), so the figures are the same bits in any order.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "parallel_work.h"

namespace flange::diagnose {

// How long the last piece of each kind run in this process took (wall seconds, its helpers
// included), read by the next map of pieces of those kinds. Thread-safe.
void note_piece_seconds(const std::string& kind, double seconds);
// The claim order of pieces of `kinds`: each piece by its kind's last time, or where its kind
// was never timed, by the last time of `like[i]` (a kind whose length it tends to follow: a
// candidate's refit its screen's; empty, or "": none). Pieces with neither time first (in index
// order: nothing is known of them), then the others from the longest to the shortest (index
// order among equals).
std::vector<std::size_t> longest_first(const std::vector<std::string>& kinds,
                                       const std::vector<std::string>& like = {});

// Runs work(i) for every i in [0, kinds.size()) as parallel_map does, the pieces claimed in
// longest_first(kinds, like) order and each timed as its kind for the next map.
void run_longest_first(const std::vector<std::string>& kinds, const std::vector<std::string>& like,
                       const std::function<void(std::size_t)>& work);

// parallel_map's results, in index order, with the pieces claimed longest first.
template <typename T, typename Make>
std::vector<T> parallel_map_longest_first(const std::vector<std::string>& kinds,
                                          const Make& make,
                                          const std::vector<std::string>& like = {}) {
  std::vector<T> out(kinds.size());
  run_longest_first(kinds, like, [&](std::size_t i) { out[i] = make(i); });
  return out;
}

}  // namespace flange::diagnose
