// SPDX-License-Identifier: MIT
// How far the held-out gap shrinks once the selected effects are added: overall, in the
// where-cell and in the where-band; and the held-out traces before and after.
#pragma once

#include <optional>
#include <string>

#include "diagnosis_detail.h"
#include "recording_series.h"
#include "selection.h"

namespace flange::diagnose {

void measure_how_far(const RecordingSeries& heldout, const Selection& selection,
                     DiagnosisResult& result);

}  // namespace flange::diagnose
