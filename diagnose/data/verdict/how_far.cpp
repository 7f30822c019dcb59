// SPDX-License-Identifier: MIT
#include "how_far.h"

#include "locate.h"
#include "regions.h"
#include "series_arithmetic.h"
#include "series_statistics.h"

namespace flange::diagnose {

HowFar measure_how_far(const RecordingSeries& heldout, const Selection& selection,
                       const Location& detail, HowFar from_verdict) {
  const std::vector<double>& ho_gap = selection.raw_ho_gap;
  const std::vector<double>& current_error = selection.current_error;
  HowFar how = std::move(from_verdict);
  how.rms_before = rms_of(ho_gap);
  how.rms_after = rms_of(current_error);
  how.max_before = max_abs_of(ho_gap);
  how.max_after = max_abs_of(current_error);
  if (detail.where_region) {
    const std::vector<std::size_t> in =
        samples_in(heldout, detail.regions[*detail.where_region]);
    how.region_rms_before = rms_at(ho_gap, in);
    how.region_rms_after = rms_at(current_error, in);
    how.region_samples = in.size();
  }
  if (detail.band_hz) {
    const std::size_t segment = spectrum_segment(heldout.size());
    how.band_rms_before = band_rms(welch_psd(ho_gap, detail.fs_hz, segment), *detail.band_hz);
    how.band_rms_after = band_rms(welch_psd(current_error, detail.fs_hz, segment), *detail.band_hz);
  }
  return how;
}

// When the held-out part barely enters the cell where the calibration gap stands out most, it can
// neither confirm nor refute what lies there (a held-out session that does not heat as far): the

}  // namespace flange::diagnose
