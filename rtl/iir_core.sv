// SPDX-License-Identifier: MIT
// IIR filter core: a cascade of sections of one order, all computed on one multiply-accumulate
// unit (one DSP48E1), sequenced by an FSM over a coefficient ROM and the sample history.
//
// Fixed-point contract (docs/fixed_point.md; the same paragraph heads model/iir_core.h).
// D = SampleWidth, C = CoefWidth, P = AccWidth, F = CoefFracBits, s = FeedbackShift,
// L = SplitShift = C - 1 (17 with 18-bit words: the DSP48E1's P >>> 17), K = NumSections,
// M = SectionOrder.
// - Formats: samples in and out are Q1.(D-1) (Q1.15 by default). Inside the core every signal
//   (each section's input and output, the history) is a (D+s)-bit word, Q1.(D-1+s), D + s <= 25
//   (the DSP48E1 A port): the input enters as x << s and only sample_o is rounded back to D bits.
//   Every coefficient c, b[i] or -a[j], is split into two C-bit ROM words,
//   c = (H + W * 2^-L) * 2^-F with a signed hi word H and a lo word W in [0, 2^L); the
//   error-feedback words E[j] are signed integers (the generator takes E[j] = round(-a[j])).
// - One section k at sample n, u = its input (line k), w = its output history (line k + 1),
//   e = its rounding-error history:
//     lo    = 2^(F-1+L) + sum_i W_b[i] u[n-i] + sum_j W_a[j] w[n-j]
//     acc   = (lo >>> L) + sum_i H_b[i] u[n-i] + sum_j H_a[j] w[n-j] + sum_j E[j] e[n-j]
//     w[n]  = y_ext = saturate_(D+s)(acc >>> F)
//     e[n]  = (acc mod 2^F) - 2^(F-1), the rounding error in accumulator LSBs (F-bit signed)
//   lo and acc are P-bit two's complement and wrap like the DSP48E1 P register (the generator
//   proves that legal samples never make them wrap). Feeding the error back through E shapes
//   the rounding noise by 1 - sum_j E[j] z^-j, which cancels the 1/A(z) gain near z = 1.
// - Rounding: round half up: the preload 2^(F-1+L) becomes 2^(F-1) after the shift. sample_o is
//   rounded from the last section's y_ext: (y_ext + 2^(s-1)) >>> s for s > 0, y_ext for s = 0.
// - Saturation: each y_ext is clipped to [-2^(D-1+s), 2^(D-1+s) - 1] before it enters the
//   history; sample_o to [-2^(D-1), 2^(D-1) - 1]; any clip sets the sticky saturation_o.
// - ROM order: section 0 first; within a section W_b[0..M], W_a[1..M], H_b[0..M], H_a[1..M],
//   E[1..M]: 5M + 2 words. Load registers: K + 1 lines of M + 1 words of D + s bits, newest
//   first (line 0 is x << s, line k + 1 is y_ext of section k), and K error lines of M + 1
//   words (line k: e of section k, F-bit values). The bus target counter (BTC) counts the terms
//   in issue order and addresses each term's ROM word and load register with that one count.
// - Timing: a section issues its T = 5M + 2 terms one per cycle in the order W_b[1..M],
//   W_a[1..M], W_b[0], then H_b[0], H_b[1..M], H_a[1..M], E[1..M]. The first term starts the sum
//   at 2^(F-1+L); H_b[0] is added to P >>> L instead of P. Only W_b[0] and H_b[0] need the
//   previous section's output, so the next section's first 2M terms overlap the MAC's 3 cycles
//   of latency and its W_b[0] waits, if it must, until the cycle after that output is written
//   back. With S = T + max(0, 3 - 2M), section k's last term issues T + kS cycles after the
//   accepted EN and is written back 3 cycles later. From the cycle in which sample_valid_i is
//   accepted to the cycle in which sample_valid_o is high: LatencyCycles = T + (K - 1) * S + 4.
//   A new sample is accepted in the cycle sample_valid_o is high, so CyclesPerSample =
//   LatencyCycles too.
//
// Flags: sample_valid_i while busy_o is high drops that sample (the history is untouched) and sets
// the sticky overrun_o. Sticky flags clear on reset or with flag_clear_i; a flag event in the same
// cycle as flag_clear_i wins, so no event is lost.
//
// Channels (docs/core.md, "Channels"): NumChannels independent filters share the one MAC. Each
// sample comes with its channel_i; each channel has its own load registers, its own overrun_o and
// saturation_o bit, and, when CoefSets = NumChannels, its own coefficient set (CoefSets = 1: one
// set for all). channel_o names the channel of sample_o. A sample with channel_i >= NumChannels is
// dropped and sets the sticky channel_error_o. The timing above is per accepted sample, whatever
// its channel; a channel's history moves only on its own samples.
`default_nettype none

module iir_core #(
  // $readmemh image of the coefficient ROM: the coeffs.mem beside the iir_coeffs_pkg.sv the core
  // is built with.
  parameter RomFile = "coeffs.mem"
) (
  input  logic                                        clk_i,
  input  logic                                        rst_ni,          // synchronous, active low
  input  logic signed [iir_coeffs_pkg::SampleWidth-1:0] sample_i,
  input  logic [iir_coeffs_pkg::ChannelWidth-1:0]     channel_i,       // the sample's channel
  input  logic                                        sample_valid_i,  // EN: one cycle per sample
  output logic signed [iir_coeffs_pkg::SampleWidth-1:0] sample_o,
  output logic [iir_coeffs_pkg::ChannelWidth-1:0]     channel_o,       // sample_o's channel
  output logic                                        sample_valid_o,  // one cycle per output
  output logic                                        busy_o,          // sample_valid_i is dropped
  // Sticky, one bit per channel: a sample of that channel dropped / an output of it clipped.
  output logic [iir_coeffs_pkg::NumChannels-1:0]      overrun_o,
  output logic [iir_coeffs_pkg::NumChannels-1:0]      saturation_o,
  output logic                                        channel_error_o, // sticky: channel_i too big
  input  logic                                        flag_clear_i     // clears the sticky flags
);

  // Parameters //
  localparam int FilterOrder   = iir_coeffs_pkg::FilterOrder;
  localparam int NumSections   = iir_coeffs_pkg::NumSections;
  localparam int SectionOrder  = iir_coeffs_pkg::SectionOrder;
  localparam int SampleWidth   = iir_coeffs_pkg::SampleWidth;
  localparam int CoefWidth     = iir_coeffs_pkg::CoefWidth;
  localparam int CoefFracBits  = iir_coeffs_pkg::CoefFracBits;   // F
  localparam int FeedbackShift = iir_coeffs_pkg::FeedbackShift;  // s
  localparam int SplitShift    = iir_coeffs_pkg::SplitShift;     // L = C - 1
  localparam int AccWidth      = iir_coeffs_pkg::AccWidth;
  localparam int RomDepth      = iir_coeffs_pkg::RomDepth;       // words of one set
  localparam int NumChannels   = iir_coeffs_pkg::NumChannels;
  localparam int CoefSets      = iir_coeffs_pkg::CoefSets;       // 1, or one per channel
  localparam int ChannelWidth  = iir_coeffs_pkg::ChannelWidth;   // max(1, clog2(NumChannels))

  localparam int Terms         = 5 * SectionOrder + 2;              // MACs per section
  localparam int LrLine        = SectionOrder + 1;                  // samples per history line
  localparam int AgeWidth      = $clog2(LrLine);                    // slot within a line
  localparam int LineWidth     = $clog2(NumSections + 1);           // line number
  localparam int LrAddrWidth   = LineWidth + AgeWidth;
  localparam int LrSlots       = 1 << LrAddrWidth;                  // lines padded to 2^AgeWidth
  localparam int LrDepth       = NumChannels * LrSlots;             // channel c from c * LrSlots
  localparam int LrFullWidth   = LrDepth > 1 ? $clog2(LrDepth) : 1;
  // Error lines: K lines (one per section) of M + 1 slots, addressed like the history lines.
  localparam int ErrLineBits   = $clog2(NumSections);               // 0 for one section
  localparam int ErrAddrWidth  = ErrLineBits + AgeWidth;
  localparam int ErrSlots      = 1 << ErrAddrWidth;
  localparam int ErrDepth      = NumChannels * ErrSlots;            // channel c from c * ErrSlots
  localparam int ErrFullWidth  = ErrDepth > 1 ? $clog2(ErrDepth) : 1;
  localparam int ErrWidth      = CoefFracBits;                      // e: F-bit signed
  localparam int RomWords      = CoefSets * RomDepth;               // set c from c * RomDepth
  localparam int RomFullWidth  = RomWords > 1 ? $clog2(RomWords) : 1;
  localparam int ExtWidth      = SampleWidth + FeedbackShift;       // y_ext: history word
  localparam int AWidth        = ExtWidth;                          // multiplier A operand
  localparam int MacLatency    = 3;                                 // iir_mac: A/B, M, P
  // S = T + max(0, 3 - 2M): W_b[0] of the next section waits for the write-back.
  localparam int SectionPitch  = 2 * SectionOrder >= MacLatency ? Terms :
                                 Terms + MacLatency - 2 * SectionOrder;
  localparam int LatencyCycles = Terms + (NumSections - 1) * SectionPitch + MacLatency + 1;
  localparam int BtcWidth      = RomDepth > 1 ? $clog2(RomDepth) : 1;

  localparam logic signed [SampleWidth-1:0] SAMPLE_MAX = {1'b0, {(SampleWidth - 1){1'b1}}};
  localparam logic signed [SampleWidth-1:0] SAMPLE_MIN = {1'b1, {(SampleWidth - 1){1'b0}}};
  localparam logic signed [ExtWidth-1:0]    EXT_MAX    = {1'b0, {(ExtWidth - 1){1'b1}}};
  localparam logic signed [ExtWidth-1:0]    EXT_MIN    = {1'b1, {(ExtWidth - 1){1'b0}}};
  // 2^(s-1), half an LSB of a sample in y_ext units (0 when s = 0).
  localparam logic [ExtWidth:0]             ROUND_HALF = ((ExtWidth + 1)'(1) << FeedbackShift) >> 1;
  // The error's sign bit: e = (acc mod 2^F) - 2^(F-1) is acc's low F bits with this bit flipped.
  localparam logic [ErrWidth-1:0]           ERR_FLIP   = ErrWidth'(1) << (CoefFracBits - 1);

  // Elaboration checks: a set that breaks the contract must not build //
  if (RomDepth != NumSections * Terms) begin : g_bad_rom_depth
    $error("iir_core: RomDepth must equal NumSections * (5 * SectionOrder + 2)");
  end
  if (FilterOrder > NumSections * SectionOrder) begin : g_bad_order
    $error("iir_core: FilterOrder exceeds NumSections * SectionOrder");
  end
  if (FeedbackShift < 0) begin : g_bad_shift
    $error("iir_core: FeedbackShift must be >= 0");
  end
  if (SplitShift != CoefWidth - 1) begin : g_bad_split
    $error("iir_core: SplitShift must equal CoefWidth - 1");
  end
  if (CoefFracBits < 1 || CoefFracBits > ExtWidth) begin : g_bad_frac
    $error("iir_core: need 1 <= CoefFracBits <= SampleWidth + FeedbackShift");
  end
  if (AccWidth < CoefFracBits + ExtWidth || AccWidth < CoefFracBits + SplitShift) begin : g_bad_acc
    $error("iir_core: need CoefFracBits + max(SampleWidth + FeedbackShift, SplitShift) <= AccWidth");
  end
  if (AWidth + CoefWidth > AccWidth) begin : g_bad_product
    $error("iir_core: the product (SampleWidth + FeedbackShift + CoefWidth) exceeds AccWidth");
  end
  if (NumChannels < 1 || (CoefSets != 1 && CoefSets != NumChannels)) begin : g_bad_channels
    $error("iir_core: need NumChannels >= 1 and CoefSets = 1 or NumChannels");
  end
  if (ChannelWidth != (NumChannels > 1 ? $clog2(NumChannels) : 1)) begin : g_bad_channel_width
    $error("iir_core: ChannelWidth must be max(1, clog2(NumChannels))");
  end

  // sample_o for the last section's y_ext: (y_ext + 2^(s-1)) >>> s, saturated. The sum is one bit
  // wider than y_ext, so it cannot wrap; its shifted value fits the sample format when its two top
  // bits agree. Only the positive rail can be reached: y_ext >= 2^(D-1+s) - 2^(s-1).
  function automatic logic [SampleWidth-1:0] round_to_sample(logic [ExtWidth-1:0] y_ext);
    logic [ExtWidth:0] sum;
    sum = {y_ext[ExtWidth-1], y_ext} + ROUND_HALF;
    if (sum[ExtWidth] == sum[ExtWidth-1]) round_to_sample = sum[ExtWidth-1:FeedbackShift];
    else round_to_sample = sum[ExtWidth] ? SAMPLE_MIN : SAMPLE_MAX;
  endfunction

  // Whether round_to_sample(y_ext) saturates.
  function automatic logic round_clips(logic [ExtWidth-1:0] y_ext);
    logic [ExtWidth:0] sum;
    sum = {y_ext[ExtWidth-1], y_ext} + ROUND_HALF;
    round_clips = sum[ExtWidth] != sum[ExtWidth-1];
  endfunction

  typedef enum logic [1:0] {
    StIdle   = 2'd0,  // wait for EN
    StIssue  = 2'd1,  // issue one term per cycle (BTC counting), or wait for a W_b[0] operand
    StFinish = 2'd2   // every term issued: wait for the last section's write-back
  } state_e;

  state_e                                state_q, state_d;
  logic [BtcWidth-1:0]                   btc_q, btc_d;      // bus target counter
  // A section's last term, issued MacLatency cycles ago, has reached the accumulator when
  // wb_pipe_q[MacLatency-1] is high: that cycle rounds, saturates and writes it back.
  logic [MacLatency-1:0]                 wb_pipe_q, wb_pipe_d;
  logic [LineWidth-1:0]                  wb_sec_q, wb_sec_d;  // section of the next write-back
  logic [ChannelWidth-1:0]               chan_q, chan_d;      // channel of the sample in flight
  logic signed [SampleWidth-1:0]         out_q, out_d;
  logic [ChannelWidth-1:0]               out_chan_q, out_chan_d;
  logic                                  valid_q, valid_d;
  logic [NumChannels-1:0]                overrun_q, overrun_d;
  logic [NumChannels-1:0]                saturation_q, saturation_d;
  logic                                  channel_error_q, channel_error_d;

  // Coefficient ROM //
  logic [CoefWidth-1:0] rom [RomWords];
  initial $readmemh(RomFile, rom);

  // Load registers: a circular buffer per line in distributed RAM (LUTRAM, a few LUTs instead of
  // a wide multiplexer over flip-flops). An EN moves newest_q one slot on, so every word grows one
  // sample older without moving. Line l, age a lives at {l, (newest - a) mod (M + 1)}. A RAM
  // cannot be reset: filled_q counts the samples accepted since reset (up to M + 1), and a word
  // older than that reads as zero, as a cleared register would. (A word of age a in any line
  // holds a value once more than a samples were accepted: line k + 1's age 0 is read only after
  // section k wrote it.) Each channel has its own lines (from channel * LrSlots), its own newest
  // slot and its own count, kept in newest_mem_q and filled_mem_q. An EN reads channel_i's pair
  // there, moves it one sample on, and writes it back; newest_q and filled_q hold the moved pair
  // of the sample in flight. The error lines live in a second RAM of the same shape (K lines of
  // F-bit words, from channel * ErrSlots), with the same pointers: section k writes its y_ext to
  // line k + 1 and its error to error line k at age 0 in the same cycle.
  // Timing: every RAM address comes from registers (chan_q, newest_q, the BTC), never from
  // channel_i: with twelve channels the channel bits drive some 300 RAM address pins, and a path
  // from the core's input through them would not close at 100 MHz (docs/synthesis.md). So x[n]
  // enters line 0 in the cycle after the EN (x_pending_q), from x_q; the first term that reads
  // it, W_b[0] of section 0, issues 2M cycles later.
  logic [ExtWidth-1:0]    lr_ram [LrDepth];
  logic [ErrWidth-1:0]    err_ram [ErrDepth];
  // Per channel c, at bits [c * width +: width] (flat: Yosys 0.23 reads no packed 2-D arrays).
  logic [NumChannels*AgeWidth-1:0]     newest_mem_q;  // slot of age 0
  logic [NumChannels*(AgeWidth+1)-1:0] filled_mem_q;  // samples accepted since reset, up to M + 1
  // Whether a channel_i value names a channel: a ChannelWidth-bit compare (a 32-bit one costs a
  // carry chain), none when every value does.
  localparam logic EveryValueIsAChannel = NumChannels == (1 << ChannelWidth);
  function automatic logic channel_exists(logic [ChannelWidth-1:0] chan);
    channel_exists = EveryValueIsAChannel || chan < ChannelWidth'(NumChannels);
  endfunction

  // Where channel c's newest slot and count start in the flat vectors (constant 0 for one channel).
  function automatic int newest_base(logic [ChannelWidth-1:0] chan);
    newest_base = NumChannels == 1 ? 0 : 32'(chan) * AgeWidth;
  endfunction
  function automatic int filled_base(logic [ChannelWidth-1:0] chan);
    filled_base = NumChannels == 1 ? 0 : 32'(chan) * (AgeWidth + 1);
  endfunction

  logic [ChannelWidth-1:0] cur_chan;                   // the channel whose lines are addressed
  logic [AgeWidth-1:0]    newest_q, newest_d;          // the sample in flight's newest slot
  logic [AgeWidth:0]      filled_q, filled_d;          // and its count
  logic [AgeWidth-1:0]    en_newest;                   // channel_i's pair, moved on by an EN
  logic [AgeWidth:0]      en_filled;
  logic                   en_accept;                   // an EN is accepted in this cycle
  logic signed [SampleWidth-1:0] x_q, x_d;             // x[n], written to line 0 ...
  logic                   x_pending_q, x_pending_d;    // ... in the cycle after its EN
  logic                   lr_we;
  logic [LrAddrWidth-1:0] lr_waddr, lr_raddr;          // within the channel's lines
  logic [LrFullWidth-1:0] lr_waddr_full, lr_raddr_full;
  logic [ExtWidth-1:0]    lr_wdata;
  logic                    err_we;
  logic [ErrAddrWidth-1:0] err_waddr, err_raddr;       // within the channel's error lines
  logic [ErrFullWidth-1:0] err_waddr_full, err_raddr_full;
  logic [ErrWidth-1:0]     err_wdata;

  assign cur_chan = chan_q;

  // channel_i's pair as an EN moves it: the history grows one sample older in every line.
  logic [AgeWidth-1:0] in_newest;
  logic [AgeWidth:0]   in_filled;
  assign in_newest = channel_exists(channel_i) ? newest_mem_q[newest_base(channel_i) +: AgeWidth]
                                               : '0;
  assign in_filled = channel_exists(channel_i) ? filled_mem_q[filled_base(channel_i) +: AgeWidth+1]
                                               : '0;
  assign en_newest = (in_newest == AgeWidth'(SectionOrder)) ? '0 : in_newest + 1'b1;
  assign en_filled = (in_filled == (AgeWidth + 1)'(LrLine)) ? in_filled : in_filled + 1'b1;
  assign en_accept = (state_q == StIdle) && sample_valid_i && channel_exists(channel_i);

  // Channel c's word at `addr` within its lines: c * LrSlots + addr, which is {c, addr} since
  // LrSlots is a power of two (no adder). One channel drops the always-0 channel bit.
  /* verilator lint_off UNUSEDSIGNAL */
  function automatic logic [LrFullWidth-1:0] lr_full_addr(logic [ChannelWidth-1:0] chan,
                                                          logic [LrAddrWidth-1:0] addr);
    logic [ChannelWidth+LrAddrWidth-1:0] both;
    both         = {chan, addr};
    lr_full_addr = both[LrFullWidth-1:0];
  endfunction
  function automatic logic [ErrFullWidth-1:0] err_full_addr(logic [ChannelWidth-1:0] chan,
                                                            logic [ErrAddrWidth-1:0] addr);
    logic [ChannelWidth+ErrAddrWidth-1:0] both;
    both          = {chan, addr};
    err_full_addr = both[ErrFullWidth-1:0];
  endfunction
  // Error line `line` (section `line`, < K), slot `slot`: {line, slot}; one section has no line
  // bits (the shift drops them).
  function automatic logic [ErrAddrWidth-1:0] err_addr_of(logic [LineWidth-1:0] line,
                                                          logic [AgeWidth-1:0] slot);
    err_addr_of = ErrAddrWidth'(ErrAddrWidth'(line) << AgeWidth) | ErrAddrWidth'(slot);
  endfunction
  /* verilator lint_on UNUSEDSIGNAL */
  assign lr_waddr_full  = lr_full_addr(cur_chan, lr_waddr);
  assign lr_raddr_full  = lr_full_addr(cur_chan, lr_raddr);
  assign err_waddr_full = err_full_addr(cur_chan, err_waddr);
  assign err_raddr_full = err_full_addr(cur_chan, err_raddr);

  always_ff @(posedge clk_i) begin
    if (lr_we) lr_ram[lr_waddr_full] <= lr_wdata;
  end
  always_ff @(posedge clk_i) begin
    if (err_we) err_ram[err_waddr_full] <= err_wdata;
  end

  // The slot of the word `age` samples older than the one in slot `newest`.
  function automatic logic [AgeWidth-1:0] slot_of(logic [AgeWidth-1:0] newest,
                                                  logic [AgeWidth:0] age);
    logic [AgeWidth+1:0] back;
    back = {2'b0, newest} - {1'b0, age};
    if (back[AgeWidth+1]) back = back + (AgeWidth + 2)'(LrLine);  // wrapped below slot 0
    slot_of = back[AgeWidth-1:0];
  endfunction

  // BTC decode: the term's ROM word, its role, and the load register it multiplies //
  // Issue position p of section k (M = SectionOrder):
  //   p < M            W_b[p+1]          line k,     age p + 1        ROM offset p + 1
  //   M <= p < 2M      W_a[p-M+1]        line k + 1, age p - M + 1    ROM offset p + 1
  //   p = 2M           W_b[0]            line k,     age 0            ROM offset 0
  //   p = 2M + 1       H_b[0]  (P >>> L) line k,     age 0            ROM offset p
  //   2M + 1 < p <= 3M + 1  H_b[p-2M-1]  line k,     age p - 2M - 1   ROM offset p
  //   3M + 1 < p <= 4M + 1  H_a[p-3M-1]  line k + 1, age p - 3M - 1   ROM offset p
  //   4M + 1 < p <= 5M + 1  E[p-4M-1]    error line k, age p - 4M - 1 ROM offset p
  // ROM words stay in ROM order (W_b[0..M], W_a[1..M], H_b[0..M], H_a[1..M], E[1..M]); the
  // decoder maps the count to the address, which synthesis folds into the ROM's LUTs.
  logic                       term_first, term_last, term_shift, term_error, term_needs_previous;
  logic [BtcWidth-1:0]        rom_addr;
  logic [LineWidth-1:0]       rd_line;
  logic [AgeWidth:0]          rd_age;  // 0..M
  always_comb begin
    term_first          = 1'b0;
    term_last           = 1'b0;
    term_shift          = 1'b0;
    term_error          = 1'b0;
    term_needs_previous = 1'b0;
    rom_addr            = '0;
    rd_line             = '0;
    rd_age              = '0;
    for (int k = 0; k < NumSections; k++) begin
      for (int p = 0; p < Terms; p++) begin
        if (btc_q == BtcWidth'(k * Terms + p)) begin
          term_first = (p == 0);
          term_last  = (p == Terms - 1);
          if (p < SectionOrder) begin
            // W_b[p+1] multiplies u_k[n-p-1] (line k).
            rom_addr = BtcWidth'(k * Terms + p + 1);
            rd_line  = LineWidth'(k);
            rd_age   = (AgeWidth + 1)'(p + 1);
          end else if (p < 2 * SectionOrder) begin
            // W_a[j], j = p - M + 1, multiplies w_k[n-j] (line k + 1).
            rom_addr = BtcWidth'(k * Terms + p + 1);
            rd_line  = LineWidth'(k + 1);
            rd_age   = (AgeWidth + 1)'(p - SectionOrder + 1);
          end else if (p <= 2 * SectionOrder + 1) begin
            // W_b[0], then H_b[0] (added to P >>> L), multiply u_k[n]: for k > 0 the output of
            // section k - 1, which may still be computing.
            term_shift          = (p == 2 * SectionOrder + 1);
            term_needs_previous = (k > 0);
            rom_addr            = BtcWidth'(p == 2 * SectionOrder ? k * Terms : k * Terms + p);
            rd_line             = LineWidth'(k);
            rd_age              = '0;
          end else if (p <= 3 * SectionOrder + 1) begin
            // H_b[i], i = p - 2M - 1, multiplies u_k[n-i] (line k).
            rom_addr = BtcWidth'(k * Terms + p);
            rd_line  = LineWidth'(k);
            rd_age   = (AgeWidth + 1)'(p - 2 * SectionOrder - 1);
          end else if (p <= 4 * SectionOrder + 1) begin
            // H_a[j], j = p - 3M - 1, multiplies w_k[n-j] (line k + 1).
            rom_addr = BtcWidth'(k * Terms + p);
            rd_line  = LineWidth'(k + 1);
            rd_age   = (AgeWidth + 1)'(p - 3 * SectionOrder - 1);
          end else begin
            // E[j], j = p - 4M - 1, multiplies e_k[n-j] (error line k).
            term_error = 1'b1;
            rom_addr   = BtcWidth'(k * Terms + p);
            rd_line    = LineWidth'(k);
            rd_age     = (AgeWidth + 1)'(p - 4 * SectionOrder - 1);
          end
        end
      end
    end
  end

  logic [AgeWidth-1:0]        rd_slot;
  logic                       rd_filled;  // the word of age rd_age holds a value
  logic signed [ExtWidth-1:0] lr_word;
  logic signed [ErrWidth-1:0] err_word;
  assign rd_slot   = slot_of(newest_q, rd_age);
  assign rd_filled = filled_q > rd_age;
  assign lr_raddr  = {rd_line, rd_slot};
  assign err_raddr = err_addr_of(rd_line, rd_slot);
  assign lr_word   = rd_filled ? $signed(lr_ram[lr_raddr_full]) : '0;
  assign err_word  = rd_filled ? $signed(err_ram[err_raddr_full]) : '0;

  // Operands //
  logic                          issue;
  logic signed [AWidth-1:0]      mac_a;
  logic signed [CoefWidth-1:0]   mac_b;
  logic signed [AccWidth-1:0]    mac_p;

  // Every term takes a (D+s)-bit word as it is: the history word (x << s in line 0, y_ext in the
  // others) or the F-bit error, sign-extended (F <= D + s). The two selects are kept as signals of
  // their own: with the core flattened, ABC would otherwise fold the BTC decoder into every bit
  // of A (a mux tree of LUT6, MUXF7 and MUXF8 per bit, about 85 LUTs more).
  (* keep *) logic sel_lr, sel_err;
  assign sel_lr  = issue & ~term_error;
  assign sel_err = issue & term_error;
  assign mac_a   = ({AWidth{sel_lr}} & lr_word) | ({AWidth{sel_err}} & AWidth'(err_word));
  // One set: the decoded address; a set per channel: that channel's set.
  logic [RomFullWidth-1:0] rom_full_addr;
  assign rom_full_addr = CoefSets == 1 ? RomFullWidth'(rom_addr) :
                                         RomFullWidth'(32'(chan_q) * RomDepth + 32'(rom_addr));
  assign mac_b = $signed(rom[rom_full_addr]);

  iir_mac #(
    .AWidth    (AWidth),
    .BWidth    (CoefWidth),
    .AccWidth  (AccWidth),
    .PreloadBit(CoefFracBits - 1 + SplitShift),
    .ShiftBits (SplitShift)
  ) u_mac (
    .clk_i,
    .rst_ni,
    .a_i    (mac_a),
    .b_i    (mac_b),
    .first_i(issue & term_first),
    .shift_i(issue & term_shift),
    .p_o    (mac_p)
  );

  // Round (preloaded), saturate, keep the error //
  // y_ext = P >>> F fits D + s bits when every bit of P above its sign bit equals it.
  logic [AccWidth-CoefFracBits-ExtWidth:0] acc_top;
  logic                                    clip_ext, clip, last_writeback;
  logic signed [ExtWidth-1:0]              section_ext;
  logic [ErrWidth-1:0]                     section_err;

  assign acc_top     = mac_p[AccWidth-1:CoefFracBits+ExtWidth-1];
  assign clip_ext    = !((&acc_top) || !(|acc_top));
  assign section_ext = !clip_ext         ? mac_p[CoefFracBits+ExtWidth-1:CoefFracBits] :
                       mac_p[AccWidth-1] ? EXT_MIN : EXT_MAX;
  // e = (P mod 2^F) - 2^(F-1): P's low F bits with the top one inverted, as an F-bit signed word.
  assign section_err = mac_p[CoefFracBits-1:0] ^ ERR_FLIP;

  // FSM //
  // W_b[0] and H_b[0] of section k > 0 wait while section k - 1's last term is still in the MAC
  // pipeline (only W_b[0] ever waits: H_b[0] follows it).
  logic stall;
  logic writeback;
  assign stall          = term_needs_previous & (|wb_pipe_q);
  assign writeback      = wb_pipe_q[MacLatency-1];
  assign last_writeback = wb_sec_q == LineWidth'(NumSections - 1);
  // Any section's y_ext clip; the last one's also sample_o's clip.
  assign clip           = clip_ext | (last_writeback & round_clips(section_ext));

  always_comb begin
    state_d    = state_q;
    btc_d      = btc_q;
    wb_sec_d   = wb_sec_q;
    chan_d     = chan_q;
    newest_d   = newest_q;
    filled_d   = filled_q;
    out_d      = out_q;
    out_chan_d = out_chan_q;
    x_d        = x_q;
    x_pending_d = 1'b0;
    valid_d   = 1'b0;
    issue     = 1'b0;
    lr_we     = 1'b0;
    lr_waddr  = '0;
    lr_wdata  = '0;
    err_we    = 1'b0;
    err_waddr = '0;
    err_wdata = '0;

    unique case (state_q)
      StIdle: begin
        if (en_accept) begin
          // EN: the channel's pointers move on (newest_mem_q, below); x[n] waits in x_q.
          newest_d    = en_newest;
          filled_d    = en_filled;
          x_d         = sample_i;
          x_pending_d = 1'b1;
          btc_d       = '0;
          wb_sec_d    = '0;
          chan_d      = channel_i;
          state_d     = StIssue;
        end
      end
      StIssue: begin
        // The cycle after the EN: x[n] << s enters line 0 at the new newest slot. No write-back
        // can fall in this cycle: the previous sample's last one ended its computation.
        if (x_pending_q) begin
          lr_we    = 1'b1;
          lr_waddr = {LineWidth'(0), newest_q};
          lr_wdata = ExtWidth'(x_q) <<< FeedbackShift;
        end
        if (!stall) begin
          issue = 1'b1;
          if (btc_q == BtcWidth'(RomDepth - 1)) begin
            btc_d   = '0;
            state_d = StFinish;
          end else begin
            btc_d = btc_q + 1'b1;
          end
        end
      end
      StFinish: ;  // the write-back below ends it
      default: state_d = StIdle;
    endcase

    if (writeback) begin
      // A section's sum is complete: its y_ext becomes the newest entry of the next line, its
      // rounding error the newest entry of its error line.
      lr_we     = 1'b1;
      lr_waddr  = {wb_sec_q + LineWidth'(1), newest_q};
      lr_wdata  = section_ext;
      err_we    = 1'b1;
      err_waddr = err_addr_of(wb_sec_q, newest_q);
      err_wdata = section_err;
      wb_sec_d  = wb_sec_q + 1'b1;
      if (last_writeback) begin
        out_d      = $signed(round_to_sample(section_ext));
        out_chan_d = chan_q;
        valid_d    = 1'b1;
        state_d    = StIdle;
      end
    end
  end

  assign wb_pipe_d = {wb_pipe_q[MacLatency-2:0], issue & term_last};

  // Sticky flags //
  // The bit of channel c: one-hot of c, or nothing for a channel out of range.
  function automatic logic [NumChannels-1:0] channel_bit(logic [ChannelWidth-1:0] chan);
    channel_bit = '0;
    for (int c = 0; c < NumChannels; c++) channel_bit[c] = (32'(chan) == c);
  endfunction
  logic channel_i_ok;
  assign channel_i_ok    = channel_exists(channel_i);
  assign overrun_d       = (overrun_q & ~{NumChannels{flag_clear_i}}) |
                           ({NumChannels{sample_valid_i & (state_q != StIdle)}} &
                            channel_bit(channel_i));
  assign saturation_d    = (saturation_q & ~{NumChannels{flag_clear_i}}) |
                           ({NumChannels{writeback & clip}} & channel_bit(chan_q));
  assign channel_error_d = (channel_error_q & ~flag_clear_i) | (sample_valid_i & ~channel_i_ok);

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      state_q         <= StIdle;
      btc_q           <= '0;
      wb_pipe_q       <= '0;
      wb_sec_q        <= '0;
      chan_q          <= '0;
      newest_mem_q    <= '0;
      filled_mem_q    <= '0;
      newest_q        <= '0;
      filled_q        <= '0;
      x_pending_q     <= 1'b0;
      out_q           <= '0;
      out_chan_q      <= '0;
      valid_q         <= 1'b0;
      overrun_q       <= '0;
      saturation_q    <= '0;
      channel_error_q <= 1'b0;
    end else begin
      state_q         <= state_d;
      btc_q           <= btc_d;
      wb_pipe_q       <= wb_pipe_d;
      wb_sec_q        <= wb_sec_d;
      chan_q          <= chan_d;
      newest_q        <= newest_d;
      filled_q        <= filled_d;
      x_pending_q     <= x_pending_d;
      if (en_accept) begin
        newest_mem_q[newest_base(channel_i) +: AgeWidth]   <= en_newest;
        filled_mem_q[filled_base(channel_i) +: AgeWidth+1] <= en_filled;
      end
      out_q           <= out_d;
      out_chan_q      <= out_chan_d;
      valid_q         <= valid_d;
      overrun_q       <= overrun_d;
      saturation_q    <= saturation_d;
      channel_error_q <= channel_error_d;
    end
  end

  // x[n] needs no reset: it is written to line 0 only in the cycle after its EN.
  always_ff @(posedge clk_i) x_q <= x_d;

  assign sample_o        = out_q;
  assign channel_o       = out_chan_q;
  assign sample_valid_o  = valid_q;
  assign busy_o          = (state_q != StIdle);
  assign overrun_o       = overrun_q;
  assign saturation_o    = saturation_q;
  assign channel_error_o = channel_error_q;

  // Assertions //
`ifndef SYNTHESIS
  // The write-back port is free: an EN is never accepted while a section is being written back.
  always @(posedge clk_i) begin
    if (rst_ni && writeback) begin
      assert (state_q != StIdle) else $error("iir_core: write-back while idle");
    end
  end

  // W_b[0] and H_b[0] of section k > 0 are never issued before section k - 1 was written back.
  always @(posedge clk_i) begin
    if (rst_ni && issue && term_needs_previous) begin
      assert (wb_pipe_q == '0)
      else $error("iir_core: W_b[0] or H_b[0] issued before its operand exists");
    end
  end

  // sample_valid_o comes LatencyCycles after the accepted EN (docs/core.md, the model agrees).
  int unsigned cycles_since_en;
  always @(posedge clk_i) begin
    if (rst_ni && valid_q) begin
      assert (cycles_since_en == LatencyCycles)
      else $error("iir_core: output after %0d cycles, expected %0d", cycles_since_en,
                  LatencyCycles);
    end
    if (!rst_ni) cycles_since_en <= 0;
    else if (state_q == StIdle && sample_valid_i) cycles_since_en <= 1;
    else if (cycles_since_en != 0) cycles_since_en <= cycles_since_en + 1;
  end
`endif

endmodule
