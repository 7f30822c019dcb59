// SPDX-License-Identifier: MIT
// The improved twin `flange diagnose` hands back as twin.json (docs/diagnose.md, "The improved
// twin"): the twin it started from, with the selected effects as the selection left them (the
// library picks with their fitted parameters, the converter with its code boundaries), the free
// shapes as one table (sim's tabulated effect, fitted by table_fit.h), mount motion at its
// recognised size and the white noise at its estimated level. Each finding says how the twin holds
// it, or that it cannot.
#pragma once

#include <string>
#include <vector>

#include "diagnosis.h"
#include "sensor_twin.h"
#include "white_noise.h"

namespace flange::diagnose {

struct Parts;
struct Selection;

// How the improved twin holds one finding.
struct HeldFinding {
  std::string name;  // the finding's class
  // "library effect", "library effect and table", "table", "converter", "white noise" (a grid
  // whose codes are not replayed), "mount motion", "session's own lines" or "not held".
  std::string held_as;
  std::string note;  // one sentence: what the twin holds of it, or why it cannot
};

struct ImprovedTwin {
  sim::TwinConfig twin;
  std::vector<HeldFinding> findings;  // in the diagnosis's order
  // The table's misfit to what the free shapes add, RMS over each part (calibration, held-out),
  // V; empty without a table.
  std::vector<double> table_misfit_rms_v;
  // The classes whose free shape is held as its library member (a lag's mean delay, a skew's
  // mean) with the table taking what the member leaves.
  std::vector<std::string> members;
  std::string summary;  // one sentence: what was added to the twin, or why nothing was
};

// The improved twin of `diagnosis` (its status and findings), from the twin it started from
// (`given`), the parts, the selection's final state and the white noise the diagnosis reports.
ImprovedTwin improved_twin(const Parts& parts, const Selection& selection,
                           const Diagnosis& diagnosis, const WhiteNoise& white,
                           const sim::TwinConfig& given);

}  // namespace flange::diagnose
