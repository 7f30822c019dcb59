// SPDX-License-Identifier: MIT
#include "channel_sets.h"

#include <fmt/format.h>

#include <algorithm>

#include "design_error.h"

namespace flange::coeffs {

namespace {

std::vector<DesignRecord> design_each(DesignRequest request, const std::vector<double>& fc_hz,
                                      const std::string& generated_by) {
  std::vector<DesignRecord> records;
  for (const double fc : fc_hz) {
    request.fc_hz = fc;
    records.push_back(generate_design(request, generated_by));
  }
  return records;
}

}  // namespace

DesignRecord generate_channel_designs(const DesignRequest& request,
                                      const std::vector<double>& channel_fc_hz,
                                      const std::string& generated_by) {
  const int count = static_cast<int>(channel_fc_hz.size());
  if (count < 1 || count > kMaxChannels) {
    throw BadArgument(fmt::format("--channel-fc: {} cut-offs; give 1 to {}, one per channel",
                                  count, kMaxChannels));
  }
  if (!request.order) throw BadArgument("--channel-fc: give the order of every channel (--order)");
  std::vector<DesignRecord> records = design_each(request, channel_fc_hz, generated_by);
  const std::vector<DesignRecord> alone = records;

  // One format for all: the smallest feedback shift and fraction any channel takes on its own.
  int shift = records.front().quantized.feedback_shift;
  int frac = records.front().quantized.coef_frac_bits;
  for (const DesignRecord& r : records) {
    shift = std::min(shift, r.quantized.feedback_shift);
    frac = std::min(frac, r.quantized.coef_frac_bits);
  }
  DesignRequest shared = request;
  shared.max_feedback_shift = shift;
  shared.max_coef_frac_bits = frac;
  records = design_each(shared, channel_fc_hz, generated_by);

  DesignRecord combined = records.front();
  combined.channels = count;
  combined.analysis.rejection.clear();  // set below, naming the channel
  for (int c = 0; c < count; ++c) {
    const DesignRecord& r = records[static_cast<std::size_t>(c)];
    if (r.quantized.coef_frac_bits != combined.quantized.coef_frac_bits ||
        r.quantized.feedback_shift != combined.quantized.feedback_shift) {
      throw DesignRejected(fmt::format(
          "channels 0 and {} need different coefficient formats (Q.{} shift {} against Q.{} "
          "shift {}); one core has one format: give the channels closer cut-offs or use two cores",
          c, combined.quantized.coef_frac_bits, combined.quantized.feedback_shift,
          r.quantized.coef_frac_bits, r.quantized.feedback_shift));
    }
    combined.quantized.acc_bits_needed =
        std::max(combined.quantized.acc_bits_needed, r.quantized.acc_bits_needed);
    if (combined.analysis.rejection.empty() && !r.analysis.rejection.empty()) {
      // Say the shared format is to blame only when the channel passes in its own.
      const bool shared_format_broke_it =
          alone[static_cast<std::size_t>(c)].analysis.rejection.empty();
      combined.analysis.rejection =
          shared_format_broke_it
              ? fmt::format("channel {} (fc = {:.6g} Hz), in the channels' shared format (Q.{}, "
                            "feedback shift {}): {}",
                            c, channel_fc_hz[static_cast<std::size_t>(c)], frac, shift,
                            r.analysis.rejection)
              : fmt::format("channel {} (fc = {:.6g} Hz): {}", c,
                            channel_fc_hz[static_cast<std::size_t>(c)], r.analysis.rejection);
    }
    combined.channel_sets.push_back({r.design, r.quantized, r.analysis});
  }
  return combined;
}

}  // namespace flange::coeffs
