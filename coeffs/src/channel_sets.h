// SPDX-License-Identifier: MIT
// A coefficient set per channel for a multichannel core: one Butterworth low-pass per channel (the
// same order and structure, each its own cut-off), all rounded into one fixed-point format, since
// the channels share the core's one contract (docs/fixed_point.md; the RTL has one Fa and one Fb).
#pragma once

#include <string>
#include <vector>

#include "design_outputs.h"
#include "generator.h"

namespace flange::coeffs {

// `request` gives everything but the cut-off: fs, order, structure, widths, limits. Each channel's
// feedback shift s is capped at the smallest any channel gets on its own (a narrower filter gives
// up fractional bits of its numerator so that all share Fb). Throws BadArgument for an invalid
// request or list (1 to kMaxChannels cut-offs, each 0 < fc < fs/2), DesignRejected when the
// channels' denominators need different formats. A channel that fails in hardware comes back as
// the record's analysis.rejection, naming the channel.
DesignRecord generate_channel_designs(const DesignRequest& request,
                                      const std::vector<double>& channel_fc_hz,
                                      const std::string& generated_by);

}  // namespace flange::coeffs
