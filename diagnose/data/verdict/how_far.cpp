// SPDX-License-Identifier: MIT
#include "how_far.h"

#include "locate.h"
#include "regions.h"
#include "series_arithmetic.h"
#include "residual_tests.h"

namespace flange::diagnose {

void measure_how_far(const RecordingSeries& heldout, const Selection& selection,
                     DiagnosisResult& result) {
  DiagnosisDetail& detail = result.detail;
  const std::vector<double>& ho_gap = selection.raw_ho_gap;
  const std::vector<double>& current_error = selection.current_error;
  HowFar& how = detail.how_far;
  how.rms_before = result.diagnosis.heldout_rms_before;
  how.rms_after = result.diagnosis.heldout_rms_after;
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
  detail.heldout_t_s = heldout.t_s;
  detail.heldout_gap_before_v = ho_gap;
  detail.heldout_gap_after_v = current_error;
}

// When the held-out part barely enters the cell where the calibration gap stands out most, it can
// neither confirm nor refute what lies there (a held-out session that does not heat as far): the

}  // namespace flange::diagnose
