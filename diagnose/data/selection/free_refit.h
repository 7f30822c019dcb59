// SPDX-License-Identifier: MIT
// Backfitting the free-shape picks: a free curve is fitted on what the picks before it leave, so
// it takes part of the effects picked after it (an offset curve of T takes some of a reading lag's
// hysteresis); once a later pick is in, each earlier free curve is fitted again on what all the
// other picks leave, and kept where that leaves less on held-out data. The classes stay; their
// shapes and the library picks' values change.
#pragma once

#include "parts.h"
#include "selection.h"

namespace flange::diagnose {

// Each free-shape pick but the last, in selection order, fitted again by its own family on what
// the other picks leave, where that lowers the held-out mean square (with what fitting its
// held-out values would take from white noise); the library picks are refitted around each
// accepted curve.
void refit_earlier_free_picks(const Parts& parts, Selection& selection);

// Each free curve of temperature picked (an offset, a gain about the range's bottom) fitted again
// on free_shapes::kFineKnots knots on what the other picks leave, where that lowers the
// held-out mean square as refit_earlier_free_picks asks. The classes are chosen on the coarser
// curves, so a finer one cannot take a class's place.
void refine_temperature_curves(const Parts& parts, Selection& selection);

}  // namespace flange::diagnose
