// SPDX-License-Identifier: MIT
// The library's classes with free shapes: after the library's pass, each of its picks in turn is
// given the free shape of its own class where that fits what the others leave better. The classes
// stay; their shapes and the library picks' values change. (A free pass picks its classes
// greedily, each free curve fitted before the picks after it and never refitted, so a class whose
// shape departs from the library's beside a second class that the library's formula explains can
// be lost there; this keeps the library pass's classes and refines their shapes.)
#pragma once

#include <cstddef>

#include "parts.h"
#include "selection.h"

namespace flange::diagnose {

// Pick `j` (a library pick) given the free shape of its own class that fits best what the other
// picks leave, when that lowers the held-out mean square by criteria::kRefinementAcceptance of
// sigma^2 (after what fitting its held-out values would take from white noise); the library picks
// are then refitted around it.
void give_pick_a_free_shape(const Parts& parts, Selection& selection, std::size_t j);

// Every pick of `library` given a free shape where it gains so (give_pick_a_free_shape).
Selection with_free_shapes_of_its_classes(const Parts& parts, const Selection& library);

}  // namespace flange::diagnose
