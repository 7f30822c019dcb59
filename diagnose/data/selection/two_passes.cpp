// SPDX-License-Identifier: MIT
#include "two_passes.h"

#include <algorithm>

#include "criteria.h"
#include "forward.h"
#include "free_refit.h"
#include "parallel_work.h"
#include "refinement.h"
#include "series_statistics.h"

namespace flange::diagnose {
// Whether the free pass replaces the library pass: it leaves less by
// criteria::kPassComparisonMargin of sigma^2, or it names fewer classes where the library pass
// named several, leaving no more than that margin more, or where both leave the noise (the
// library's formulas can split between two classes what one class of another shape explains
// alone; where both leave the noise, the fewer classes are the explanation).
bool free_pass_wins(const Selection& library, const Selection& free, bool several_classes) {
  const double left = rms_of(library.current_error);
  const double free_left = rms_of(free.current_error);
  const double sigma = std::min(library.noise_v, free.noise_v);
  const double margin = criteria::kPassComparisonMargin * sigma * sigma;
  const bool leaves_less = left * left - free_left * free_left >= margin;
  const bool both_leave_the_noise =
      left <= criteria::kExplainedRatio * sigma && free_left <= criteria::kExplainedRatio * sigma;
  const bool fewer_classes = !free.picks.empty() && free.picks.size() < library.picks.size() &&
                             (free_left * free_left - left * left < margin || both_leave_the_noise);
  return leaves_less || (several_classes && fewer_classes);
}

namespace {

// The library's classes with shapes of their own, when they leave less by
// criteria::kRefinementAcceptance of sigma^2: whether or not the library's formulas explained
// the pair, a shape that departs from them is reported.
Selection with_shapes_where_they_gain(const Parts& parts, Selection selection) {
  if (selection.picks.empty()) return selection;
  Selection refined = with_free_shapes_of_its_classes(parts, selection);
  const double before = rms_of(selection.current_error), after = rms_of(refined.current_error);
  const double margin = criteria::kRefinementAcceptance * selection.noise_v * selection.noise_v;
  return before * before - after * after >= margin ? refined : selection;
}

// The library pass, or the free pass where it wins (free_pass_wins).
Selection pass_taken(const Parts& parts, const DiagnoseOptions& options,
                     const std::optional<AdcGrid>& cal_grid, const Selection& start) {
  // The library candidates of a round the free pass weighs as the library pass did.
  LibraryRounds rounds;
  Selection library = start;
  select_bias_effects(parts, rounds, options, cal_grid, library);
  const bool several_classes = library.picks.size() > 1;
  const auto explained_by_one_class = [&](const Selection& selection) {
    return rms_of(selection.current_error) <= criteria::kExplainedRatio * selection.noise_v &&
           !several_classes;
  };
  if (explained_by_one_class(library)) {
    return with_shapes_where_they_gain(parts, std::move(library));
  }
  // The refinement and the free pass do not depend on each other: they run at once, and the
  // refined selection is taken alone when it explains with one class (the free pass then unused).
  Selection free = start;
  free.free_shapes = true;
  run_both([&] { library = with_shapes_where_they_gain(parts, library); },
           [&] { select_bias_effects(parts, rounds, options, cal_grid, free); });
  return explained_by_one_class(library) || !free_pass_wins(library, free, several_classes)
             ? std::move(library)
             : std::move(free);
}

}  // namespace

Selection select_in_two_passes(const Parts& parts, const DiagnoseOptions& options,
                               const std::optional<AdcGrid>& cal_grid, const Selection& start) {
  Selection chosen = pass_taken(parts, options, cal_grid, start);
  // With the classes chosen, each picked curve of temperature on finer knots (free_refit.h).
  refine_temperature_curves(parts, chosen);
  return chosen;
}

}  // namespace flange::diagnose
