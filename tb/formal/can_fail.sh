#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Shows that every formal proof can fail: breaks the RTL or a property in a copy of the tree, one
# mutation at a time, and requires tb/formal/prove.sh to reject it (docs/formal.md).
#   tb/formal/can_fail.sh [PROPERTY...]   (default: every mutation below)
# Exit status 0: every selected mutation was caught.
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"

# property # set (- for none) # file # sed expression # the break
mutations=(
  "LatencyExact#measurement_sos#rtl/iir_core.sv#s/assign writeback      = wb_pipe_q\[MacLatency-1\];/assign writeback      = wb_pipe_q[MacLatency-2];/#RTL: the write-back reads the accumulator one cycle early"
  "LatencyExactFromPorts#measurement_sos#rtl/iir_core.sv#s/assign writeback      = wb_pipe_q\[MacLatency-1\];/assign writeback      = wb_pipe_q[MacLatency-2];/#RTL: the write-back reads the accumulator one cycle early"
  "LatencyExact#measurement_df1#tb/formal/iir_core_props.sv#s/(NumSections - 1) \* SectionPitch + 4;  \/\/ L/(NumSections - 1) * SectionPitch + 5;  \/\/ L/#property: a wrong latency constant (L + 1)"
  "BusyOverrunAsDocumented#vehicle_sos#rtl/iir_core.sv#s/({NumChannels{sample_valid_i \& (state_q != StIdle)}} \&/({NumChannels{sample_valid_i \& (state_q == StIssue)}} \&/#RTL: a sample dropped while the core waits for its last write-back is not flagged"
  "BusyOverrunAsDocumentedFromPorts#vehicle_sos#rtl/iir_core.sv#s/({NumChannels{sample_valid_i \& (state_q != StIdle)}} \&/({NumChannels{sample_valid_i \& (state_q == StIssue)}} \&/#RTL: a sample dropped while the core waits for its last write-back is not flagged"
  "BusyOverrunAsDocumented#measurement_sos#rtl/iir_core.sv#s/      StIdle: begin/      StIdle, StFinish: begin/;s/assign en_accept = (state_q == StIdle)/assign en_accept = (state_q != StIssue)/#RTL: a sample offered while the core waits for its last write-back is taken"
  "BusyOverrunAsDocumented#measurement_df1#rtl/iir_core.sv#s/          x_pending_d = 1'b1;/          x_pending_d = 1'b0;/#RTL: x[n] never enters line 0 (the cycle after the EN writes nothing)"
  "ScheduleAsDocumented#measurement_sos#rtl/iir_core.sv#s/            state_d = StFinish;/            state_d = StIdle;/#RTL: the FSM skips StFinish (busy_o falls 3 cycles early)"
  "BtcWithinRom#measurement_sos#rtl/iir_core.sv#s/if (btc_q == BtcWidth'(RomDepth - 1)) begin/if (btc_q == BtcWidth'(RomDepth)) begin/#RTL: the BTC counts one term past the ROM"
  "LoadRegistersWithinLines#measurement_sos#rtl/iir_core.sv#s/assign en_newest = (in_newest == AgeWidth'(SectionOrder)) ? '0 : in_newest + 1'b1;/assign en_newest = in_newest + 1'b1;/#RTL: the newest-slot pointer does not wrap at M + 1 slots"
  "LoadRegistersWithinLines#measurement_sos#rtl/iir_core.sv#s/err_waddr = err_addr_of(wb_sec_q, newest_q);/err_waddr = err_addr_of(wb_sec_q + LineWidth'(1), newest_q);/#RTL: a section's error goes to the next section's error line (none after the last)"
  "AccumulatorNeverWraps#measurement_sos#rtl/iir_mac.sv#s/assign p_d    = p_base + AccWidth'(m_q);/assign p_d    = p_base + AccWidth'(\$unsigned(m_q));/#RTL: the product is zero-extended into the accumulator"
  "AccumulatorNeverWraps#vehicle_sos#rtl/iir_core.sv#s/    .first_i(issue \& term_first),/    .first_i(issue \& term_first \& (btc_q == '0)),/#RTL: only the first section restarts the sum"
  "AccumulatorNeverWraps#measurement_sos#rtl/iir_mac.sv#s/shift_m_q ? p_q >>> ShiftBits :/shift_m_q ? p_q :/#RTL: the MAC adds H_b[0] to P instead of P >>> L"
  "AccumulatorWithinGeneratorBound#measurement_sos#rtl/iir_core.sv#s/BtcWidth'(p == 2 \* SectionOrder ? k \* Terms : k \* Terms + p);/BtcWidth'(k * Terms + p);/#RTL: W_b[0] takes ROM word 2M (W_a[M]) instead of word 0"
  "ChannelsIndependent#tests/data/coeffs/loco_sets3#rtl/iir_core.sv#s/    both         = {chan, addr};/    both         = {{ChannelWidth{1'b0}}, addr};/#RTL: every channel's load registers at channel 0's address"
  "ChannelsIndependent#tests/data/coeffs/loco_sets3#rtl/iir_core.sv#s/    both          = {chan, addr};/    both          = {{ChannelWidth{1'b0}}, addr};/#RTL: every channel's error lines at channel 0's address"
  "ChannelsIndependent#tests/data/coeffs/loco_sets3#rtl/iir_core.sv#s/                            channel_bit(channel_i));/                            channel_bit(chan_q));/#RTL: a dropped sample flags the overrun of the channel in flight"
  "ChannelsIndependent#tests/data/coeffs/loco_ch4#rtl/iir_core.sv#s/        newest_mem_q\[newest_base(channel_i) +: AgeWidth\]   <= en_newest;/        newest_mem_q[newest_base(channel_i) +: AgeWidth] <= en_newest; newest_mem_q[0 +: AgeWidth] <= en_newest;/#RTL: every sample also moves channel 0's newest slot"
  "ValidOnlyWithMatchingCrc#-#rtl/board/crc8.sv#s/crc = {crc\[6:0\], 1'b0} ^ 8'h07;/crc = {crc[6:0], 1'b0} ^ 8'h0f;/#RTL: the CRC uses the wrong polynomial"
  "ValidOnlyWithMatchingCrc#-#rtl/board/frame_decoder.sv#s/ \&\& window_q\[7:0\] == crc;/;/#RTL: the decoder does not check the CRC byte"
)

selected=("$@")
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

caught=0
missed=0
for entry in "${mutations[@]}"; do
  IFS='#' read -r property set file expression what <<<"$entry"
  if [ ${#selected[@]} -gt 0 ] && [[ ! " ${selected[*]} " == *" $property "* ]]; then
    continue
  fi
  tree="$work/tree"
  rm -rf "$tree"
  mkdir -p "$tree/tb"
  mkdir -p "$tree/tests/data"
  cp -r "$root/rtl" "$root/coeffs" "$tree/"
  cp -r "$root/tests/data/coeffs" "$tree/tests/data/"
  cp -r "$root/tb/formal" "$tree/tb/"
  sed -i "$expression" "$tree/$file"
  if cmp -s "$root/$file" "$tree/$file"; then
    echo "can_fail: the mutation of $file did not apply: $expression" >&2
    exit 2
  fi
  args=("$property")
  # A set is a checked-in one's name, or a path from the root (tests/data/coeffs/...).
  if [[ "$set" == */* ]]; then
    args+=("$tree/$set")
  elif [ "$set" != "-" ]; then
    args+=("$tree/coeffs/$set")
  fi
  label="$property"
  [ "$set" = "-" ] || label="$property $set"
  if out="$(bash "$tree/tb/formal/prove.sh" "${args[@]}" 2>&1)"; then
    echo "can_fail: MISSED: $label still proven after: $what"
    missed=$((missed + 1))
  else
    echo "can_fail: caught: $label fails after: $what"
    echo "$out" | grep -E "^prove: (FAILED|assertion|a counterexample|no counterexample)" | sed 's/^/    /' | sed "s|$tree/||g"
    caught=$((caught + 1))
  fi
done
echo "$caught passed, $missed failed"
[ "$missed" -eq 0 ]
