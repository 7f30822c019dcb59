// SPDX-License-Identifier: MIT
// The sample rate of a recording and the rate the two parts of a diagnosis share.
#pragma once

#include "recording_series.h"

namespace flange::diagnose {

// The sample rate of a series from its median step (Hz). Throws InputError for fewer than two
// samples or a non-increasing time.
double sample_rate_hz(const RecordingSeries& series);

// The sample rate the two parts share. Throws InputError for a part with fewer than
// criteria::kLeastSamplesPerPart rows or unequal columns, and for parts whose rates differ by
// more than criteria::kSampleRateAgreement.
double shared_sample_rate_hz(const RecordingSeries& calibration, const RecordingSeries& heldout);

}  // namespace flange::diagnose
