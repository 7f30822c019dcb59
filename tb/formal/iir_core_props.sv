// SPDX-License-Identifier: MIT
// Formal wrapper of iir_core (the DUT is `dut`): exact latency, busy and overrun as documented,
// the documented term schedule, BTC and load-register (history and error line) addresses in
// range, and an accumulator that never wraps in either phase (lo words from the preload, then
// P >>> L and the hi and error-feedback words); proven by tb/formal/prove.sh with Yosys
// (docs/formal.md).
//
// Every input is free (any sample, any sample_valid_i, flag_clear_i and reset pattern); prove.sh
// only holds rst_ni low in the first cycle. The checks are immediate assertions in always_comb
// blocks: each holds in every cycle. Their labels start with the name of the property they
// belong to (latency_, busy_, overrun_, history_, btc_, lr_, sched_, acc_, gen_); prove.sh keeps
// the labels of one property (and of its helper invariants) per test.
`default_nettype none

module iir_core_props #(
  parameter RomFile = "coeffs.mem"  // the coeffs.mem beside the iir_coeffs_pkg.sv read with it
) (
  input logic                                          clk_i,
  input logic                                          rst_ni,
  input logic signed [iir_coeffs_pkg::SampleWidth-1:0] sample_i,
  input logic [iir_coeffs_pkg::ChannelWidth-1:0]       channel_i,
  input logic                                          sample_valid_i,
  input logic                                          flag_clear_i
);

  // Parameters: the contract in the header of rtl/iir_core.sv, restated here //
  localparam int NumSections   = iir_coeffs_pkg::NumSections;    // K
  localparam int SectionOrder  = iir_coeffs_pkg::SectionOrder;   // M
  localparam int SampleWidth   = iir_coeffs_pkg::SampleWidth;    // D
  localparam int CoefWidth     = iir_coeffs_pkg::CoefWidth;      // C
  localparam int CoefFracBits  = iir_coeffs_pkg::CoefFracBits;   // F
  localparam int FeedbackShift = iir_coeffs_pkg::FeedbackShift;  // s
  localparam int SplitShift    = iir_coeffs_pkg::SplitShift;     // L = C - 1
  localparam int AccWidth      = iir_coeffs_pkg::AccWidth;       // P
  localparam int RomDepth      = iir_coeffs_pkg::RomDepth;
  localparam int NumChannels   = iir_coeffs_pkg::NumChannels;    // N
  localparam int ChannelWidth  = iir_coeffs_pkg::ChannelWidth;
  localparam int Terms         = 5 * SectionOrder + 2;           // T: MACs per section
  localparam int LoTerms       = 2 * SectionOrder + 1;           // W_b[1..M], W_a[1..M], W_b[0]
  localparam int ShiftPos      = LoTerms;                        // H_b[0]: added to P >>> L
  localparam int HiTerms       = Terms - LoTerms;                // H_b[0..M], H_a[1..M], E[1..M]
  localparam int ErrPos        = 4 * SectionOrder + 2;           // E[1..M] from here
  localparam int SectionPitch  = Terms + (2 * SectionOrder >= 3 ? 0 : 3 - 2 * SectionOrder);  // S
  localparam int LatencyCycles = Terms + (NumSections - 1) * SectionPitch + 4;  // L
  localparam int LastIssue     = Terms + (NumSections - 1) * SectionPitch;      // T + (K-1)S
  localparam int AWidth        = SampleWidth + FeedbackShift;    // A operand: D + s bits
  localparam int ProdWidth     = AWidth + CoefWidth;
  localparam int BtcWidth      = RomDepth > 1 ? $clog2(RomDepth) : 1;
  localparam int AgeWidth      = $clog2(SectionOrder + 1);
  localparam int LineWidth     = $clog2(NumSections + 1);
  localparam int LrAddrWidth   = LineWidth + AgeWidth;
  localparam int LrFullWidth   = NumChannels * (1 << LrAddrWidth) > 1 ?
                                 $clog2(NumChannels * (1 << LrAddrWidth)) : 1;
  localparam int ErrAddrWidth  = $clog2(NumSections) + AgeWidth;  // error lines: K, no line K
  localparam int ErrFullWidth  = NumChannels * (1 << ErrAddrWidth) > 1 ?
                                 $clog2(NumChannels * (1 << ErrAddrWidth)) : 1;
  localparam int SinceWidth    = $clog2(LatencyCycles + 1);
  localparam int PosWidth      = $clog2(Terms + 1);

  // The accumulator bound of the width argument (docs/formal.md): the lo phase's rounding
  // constant plus 2M + 1 products, each a ProdWidth-bit two's complement number, then that sum
  // shifted by L plus 3M + 1 more products, must fit in P - 1 bits.
  localparam logic signed [63:0] PRELOAD    = 64'sd1 <<< (CoefFracBits - 1 + SplitShift);
  localparam logic signed [63:0] PRELOAD_HI = 64'sd1 <<< (CoefFracBits - 1);  // after >>> L
  localparam logic signed [63:0] PROD_MAX   = 64'sd1 <<< (ProdWidth - 1);  // |product| <= this
  localparam logic signed [63:0] ACC_MAX    = (64'sd1 <<< (AccWidth - 1)) - 64'sd1;
  localparam logic signed [63:0] LO_MAX     = PRELOAD + LoTerms * PROD_MAX;
  localparam logic signed [63:0] HI_MAX     = (LO_MAX >>> SplitShift) + 64'sd1 +
                                              HiTerms * PROD_MAX;
  if (LO_MAX > ACC_MAX || HI_MAX > ACC_MAX) begin : g_width_argument_fails
    $error("iir_core_props: the products of ProdWidth bits may not fit the accumulator");
  end

  // sample_o and saturation_o carry data; no property here is about their values.
  /* verilator lint_off UNUSEDSIGNAL */
  logic signed [SampleWidth-1:0] sample_o;
  /* verilator lint_on UNUSEDSIGNAL */
  logic                          sample_valid_o, busy_o;
  logic [NumChannels-1:0]        overrun_o, saturation_o;
  logic [ChannelWidth-1:0]       channel_o;
  logic                          channel_error_o;

  iir_core #(.RomFile(RomFile)) dut (
    .clk_i,
    .rst_ni,
    .sample_i,
    .channel_i,
    .sample_valid_i,
    .sample_o,
    .channel_o,
    .sample_valid_o,
    .busy_o,
    .overrun_o,
    .saturation_o,
    .channel_error_o,
    .flag_clear_i
  );

  // Internal signals of the core //
  // Yosys 0.23 has no hierarchical references: under Yosys these wires stay undriven here and
  // prove.sh connects each one to the flattened signal named in its `assign` line below. Verilator
  // reads the references as written (and checks their names and widths).
  logic [1:0]                  dut_state_q;
  logic [BtcWidth-1:0]         dut_btc_q, dut_rom_addr;
  logic                        dut_issue;
  logic [2:0]                  dut_wb_pipe_q;
  logic [LineWidth-1:0]        dut_wb_sec_q;
  logic [AgeWidth-1:0]         dut_newest_q, dut_newest_d;
  logic [AgeWidth:0]           dut_filled_q, dut_filled_d;
  logic                        dut_lr_we;
  logic [LrAddrWidth-1:0]      dut_lr_waddr, dut_lr_raddr;
  logic signed [AWidth-1:0]    dut_mac_a_q;
  logic signed [CoefWidth-1:0] dut_mac_b_q;
  logic signed [ProdWidth-1:0] dut_mac_m_q;
  logic signed [AccWidth-1:0]  dut_mac_p_q, dut_mac_p_d;
  logic                        dut_mac_first_a_q, dut_mac_first_m_q;
  logic                        dut_mac_shift_a_q, dut_mac_shift_m_q;
  logic                        dut_err_we, dut_term_error;
  logic [ErrAddrWidth-1:0]     dut_err_waddr, dut_err_raddr;
  logic [ErrFullWidth-1:0]     dut_err_waddr_full, dut_err_raddr_full;
  logic [ChannelWidth-1:0]     dut_chan_q, dut_cur_chan;
  logic [LrFullWidth-1:0]      dut_lr_waddr_full, dut_lr_raddr_full;
  logic [NumChannels*AgeWidth-1:0]     dut_newest_mem_q;
  logic [NumChannels*(AgeWidth+1)-1:0] dut_filled_mem_q;
  logic                        dut_x_pending_q;
`ifndef YOSYS
  assign dut_state_q       = dut.state_q;
  assign dut_btc_q         = dut.btc_q;
  assign dut_rom_addr      = dut.rom_addr;
  assign dut_issue         = dut.issue;
  assign dut_wb_pipe_q     = dut.wb_pipe_q;
  assign dut_wb_sec_q      = dut.wb_sec_q;
  assign dut_newest_q      = dut.newest_q;
  assign dut_newest_d      = dut.newest_d;
  assign dut_filled_q      = dut.filled_q;
  assign dut_filled_d      = dut.filled_d;
  assign dut_lr_we         = dut.lr_we;
  assign dut_lr_waddr      = dut.lr_waddr;
  assign dut_lr_raddr      = dut.lr_raddr;
  assign dut_mac_a_q       = dut.u_mac.a_q;
  assign dut_mac_b_q       = dut.u_mac.b_q;
  assign dut_mac_m_q       = dut.u_mac.m_q;
  assign dut_mac_p_q       = dut.u_mac.p_q;
  assign dut_mac_p_d       = dut.u_mac.p_d;
  assign dut_mac_first_a_q = dut.u_mac.first_a_q;
  assign dut_mac_first_m_q = dut.u_mac.first_m_q;
  assign dut_mac_shift_a_q = dut.u_mac.shift_a_q;
  assign dut_mac_shift_m_q = dut.u_mac.shift_m_q;
  assign dut_err_we        = dut.err_we;
  assign dut_term_error    = dut.term_error;
  assign dut_err_waddr     = dut.err_waddr;
  assign dut_err_raddr     = dut.err_raddr;
  assign dut_err_waddr_full = dut.err_waddr_full;
  assign dut_err_raddr_full = dut.err_raddr_full;
  assign dut_chan_q        = dut.chan_q;
  assign dut_cur_chan      = dut.cur_chan;
  assign dut_lr_waddr_full = dut.lr_waddr_full;
  assign dut_lr_raddr_full = dut.lr_raddr_full;
  assign dut_newest_mem_q  = dut.newest_mem_q;
  assign dut_filled_mem_q  = dut.filled_mem_q;
  assign dut_x_pending_q   = dut.x_pending_q;
`endif

  // Shadow model: cycles since the accepted sample //
  // A sample is accepted when sample_valid_i is high, busy_o low, rst_ni high and channel_i names
  // a channel. since_q is 1 in the next cycle, counts up to LatencyCycles (the cycle its output is
  // due) and is 0 otherwise.
  logic                  accept, channel_ok;
  logic [SinceWidth-1:0] since_q, since_d;
  assign channel_ok = 32'(channel_i) < NumChannels;
  assign accept  = rst_ni && sample_valid_i && !busy_o && channel_ok;
  assign since_d = accept ? SinceWidth'(1) :
                   (since_q != '0 && since_q != SinceWidth'(LatencyCycles)) ? since_q + 1'b1 : '0;

  // Shadow model: the sticky flags as documented //
  // overrun bit c: set by sample_valid_i of channel c while busy_o; channel_error: set by
  // sample_valid_i with a channel_i that names no channel. Cleared by flag_clear_i unless an event
  // lands at the same edge (the event wins); cleared by reset.
  logic [NumChannels-1:0] overrun_q, overrun_d, channel_bit;
  logic                   channel_error_q, channel_error_d;
  always_comb begin
    channel_bit = '0;
    for (int c = 0; c < NumChannels; c++) channel_bit[c] = 32'(channel_i) == c;
  end
  assign overrun_d = ({NumChannels{sample_valid_i && busy_o}} & channel_bit) |
                     (overrun_q & ~{NumChannels{flag_clear_i}});
  assign channel_error_d = (sample_valid_i && !channel_ok) || (channel_error_q && !flag_clear_i);

  // Shadow model: the channel of the accepted sample, and the flags one cycle ago.
  logic [ChannelWidth-1:0] served_q;
  logic [NumChannels-1:0]  saturation_prev_q;
  logic [NumChannels*AgeWidth-1:0]     newest_mem_prev_q;
  logic [NumChannels*(AgeWidth+1)-1:0] filled_mem_prev_q;
  logic                    accepted_prev_q;
  logic                    prev_valid_q;  // the previous cycle was not a reset cycle

  // Products summed in the accumulator since its last restart (a first term restarts it at the
  // preload); the d value is set beside the properties below.
  logic [PosWidth-1:0] acc_terms_q, acc_terms_d;

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      since_q         <= '0;
      overrun_q       <= '0;
      channel_error_q <= 1'b0;
      acc_terms_q     <= '0;
      served_q        <= '0;
    end else begin
      since_q         <= since_d;
      overrun_q       <= overrun_d;
      channel_error_q <= channel_error_d;
      acc_terms_q     <= acc_terms_d;
      if (accept) served_q <= channel_i;
    end
    saturation_prev_q <= saturation_o;
    newest_mem_prev_q <= dut_newest_mem_q;
    filled_mem_prev_q <= dut_filled_mem_q;
    accepted_prev_q   <= accept;
    prev_valid_q      <= rst_ni;
  end

  // The documented term schedule //
  // Section k issues its first 2M terms W_b[1..M], W_a[1..M] one per cycle from the cycle after
  // section k - 1's last term (from cycle 1 for section 0), and its other T - 2M terms, W_b[0]
  // first, one per cycle up to its last term E[M] in cycle T + kS (W_b[0] in cycle kS + 2M + 1).
  // The BTC holds the term of the cycle (during a wait, the waiting W_b[0]). All cycles count
  // from the accepted sample (since_q); a cycle c <= 0 or > T + (K-1)S issues nothing.
  // First cycle of section k: the cycle after section k - 1's last term; cycle 1 for section 0.
  function automatic int first_cycle_of(int k);
    first_cycle_of = (k == 0) ? 1 : Terms + (k - 1) * SectionPitch + 1;
  endfunction

  // The cycle in which section k issues W_b[0] (position 2M): its last T - 2M terms end in
  // cycle T + kS.
  function automatic int wb0_cycle_of(int k);
    wb0_cycle_of = k * SectionPitch + 2 * SectionOrder + 1;
  endfunction

  function automatic logic issues_at(int c);
    issues_at = 1'b0;
    for (int k = 0; k < NumSections; k++) begin
      if (c >= first_cycle_of(k) && c < first_cycle_of(k) + 2 * SectionOrder) issues_at = 1'b1;
      if (c >= wb0_cycle_of(k) && c <= Terms + k * SectionPitch) issues_at = 1'b1;
    end
  endfunction

  // Position (0..T-1, issue order) of the term the BTC holds in cycle c, 1 <= c <= T + (K-1)S.
  function automatic int position_at(int c);
    position_at = 0;
    for (int k = 0; k < NumSections; k++) begin
      if (c >= first_cycle_of(k) && c <= Terms + k * SectionPitch) begin
        position_at = (c - first_cycle_of(k) < 2 * SectionOrder) ? c - first_cycle_of(k) :
                      (c < wb0_cycle_of(k))                      ? 2 * SectionOrder :
                                                                   c - k * SectionPitch - 1;
      end
    end
  endfunction

  // Section of the term the BTC holds in cycle c, 1 <= c <= T + (K-1)S.
  function automatic int section_at(int c);
    section_at = 0;
    for (int k = 1; k < NumSections; k++) begin
      if (c > Terms + (k - 1) * SectionPitch) section_at = k;
    end
  endfunction

  // Whether a section's last term, E[M], issues in cycle c.
  function automatic logic last_issued_at(int c);
    last_issued_at = issues_at(c) && position_at(c) == Terms - 1;
  endfunction

  // Write-backs done before cycle c: section k's sum is written back in cycle T + kS + 3.
  function automatic int written_back_before(int c);
    written_back_before = 0;
    for (int k = 0; k < NumSections; k++) begin
      if (Terms + k * SectionPitch + 3 < c) written_back_before = written_back_before + 1;
    end
  endfunction

  int  since;
  logic sched_busy;
  assign since      = 32'(since_q);
  assign sched_busy = since_q != '0 && since_q != SinceWidth'(LatencyCycles);

  // Properties //
  always_comb begin
    // 1. The output comes exactly LatencyCycles after an accepted sample, and at no other time.
    latency_exact: assert (sample_valid_o == (since_q == SinceWidth'(LatencyCycles)));
    latency_since_bounded: assert (since_q <= SinceWidth'(LatencyCycles));
  end

  always_comb begin
    // 2. busy_o is high from the cycle after an accepted sample up to its output, exclusive.
    busy_exact: assert (busy_o == sched_busy);
    busy_since_bounded: assert (since_q <= SinceWidth'(LatencyCycles));
    // overrun_o is the documented sticky flag.
    overrun_as_documented: assert (overrun_o == overrun_q);
    // A sample that is not accepted leaves the history alone: only an accepted sample ages the
    // lines (newest_q, filled_q), and line 0 (the input history) is written only in the cycle
    // after an accepted sample (x[n] enters it then, from x_q).
    if (rst_ni && !accept) begin
      history_age_only_on_accept:
        assert (dut_newest_d == dut_newest_q && dut_filled_d == dut_filled_q);
    end
    if (rst_ni && since_q != SinceWidth'(1)) begin
      history_line0_only_after_accept:
        assert (!dut_lr_we || dut_lr_waddr[LrAddrWidth-1:AgeWidth] != '0);
    end
    history_x_pending_after_accept: assert (dut_x_pending_q == (since_q == SinceWidth'(1)));
  end

  always_comb begin
    // 4. The BTC addresses only ROM words; load-register reads and writes stay within their lines
    // (line <= K, slot <= M of the 2^AgeWidth slots a line is padded to).
    btc_in_rom: assert (dut_btc_q < BtcWidth'(RomDepth));
    btc_rom_addr_in_rom: assert (dut_rom_addr < BtcWidth'(RomDepth));
    lr_read_in_line: assert (dut_lr_raddr[AgeWidth-1:0] <= AgeWidth'(SectionOrder) &&
                             dut_lr_raddr[LrAddrWidth-1:AgeWidth] <= LineWidth'(NumSections));
    if (dut_lr_we) begin
      lr_write_in_line: assert (dut_lr_waddr[AgeWidth-1:0] <= AgeWidth'(SectionOrder) &&
                                dut_lr_waddr[LrAddrWidth-1:AgeWidth] <= LineWidth'(NumSections));
    end
    // The error lines: K of them (section k's errors in line k); an E term reads one of them.
    if (dut_issue && dut_term_error) begin
      lr_err_read_in_line: assert (dut_err_raddr[AgeWidth-1:0] <= AgeWidth'(SectionOrder) &&
                                   (32'(dut_err_raddr) >> AgeWidth) < NumSections);
    end
    if (dut_err_we) begin
      lr_err_write_in_line: assert (dut_err_waddr[AgeWidth-1:0] <= AgeWidth'(SectionOrder) &&
                                    (32'(dut_err_waddr) >> AgeWidth) < NumSections);
      // Written with the history, at a section's write-back: never by a sample being accepted.
      lr_err_write_with_writeback: assert (dut_lr_we && dut_wb_pipe_q[2]);
    end
    lr_newest_in_line: assert (dut_newest_q <= AgeWidth'(SectionOrder));
    lr_filled_bounded: assert (dut_filled_q <= (AgeWidth + 1)'(SectionOrder + 1));
    // Every channel's pointer and count, not only the served one's (an idle channel's are read
    // when its next sample comes).
    lr_every_pointer_in_line: assert (every_pointer_in_line);
  end

  // 5. Channels are independent (docs/core.md#channels): while a sample is computed, the core
  // serves its channel; every load-register read and write lies in that channel's lines; its
  // output carries it; a flag bit of another channel never rises from it; another channel's
  // pointer and count never move.
  always_comb begin
    if (sched_busy) begin
      channel_served_while_busy: assert (dut_chan_q == served_q && dut_cur_chan == served_q);
    end
    if (sample_valid_o) begin
      channel_of_output: assert (channel_o == served_q);
    end
    if (dut_lr_we) begin
      channel_write_own_lines:
        assert (32'(dut_lr_waddr_full) == 32'(dut_cur_chan) * (1 << LrAddrWidth) +
                                          32'(dut_lr_waddr) && 32'(dut_cur_chan) < NumChannels);
    end
    if (dut_issue) begin
      channel_read_own_lines:
        assert (32'(dut_lr_raddr_full) == 32'(served_q) * (1 << LrAddrWidth) +
                                          32'(dut_lr_raddr));
      channel_err_read_own_lines:
        assert (32'(dut_err_raddr_full) == 32'(served_q) * (1 << ErrAddrWidth) +
                                           32'(dut_err_raddr));
    end
    if (dut_err_we) begin
      channel_err_write_own_lines:
        assert (32'(dut_err_waddr_full) == 32'(dut_cur_chan) * (1 << ErrAddrWidth) +
                                           32'(dut_err_waddr) && 32'(dut_cur_chan) < NumChannels);
    end
    channel_overrun_as_documented: assert (overrun_o == overrun_q);
    channel_error_as_documented: assert (channel_error_o == channel_error_q);
    channel_served_in_range: assert (32'(served_q) < NumChannels);
    // A saturation bit rises only for the channel being served (the write-back that clipped ended
    // the cycle before, within the sample's computation).
    // Pointers and counts move only on an accepted sample, and only the accepted channel's.
    if (prev_valid_q) begin
      channel_saturation_own: assert ((saturation_o & ~saturation_prev_q &
                                       ~(NumChannels'(1) << served_q)) == '0);
      channel_pointers_still: assert (other_pointers_still);
    end
  end

  // The per-channel checks above, folded over the channels (one assertion each).
  logic every_pointer_in_line, other_pointers_still;
  always_comb begin
    every_pointer_in_line = 1'b1;
    other_pointers_still  = 1'b1;
    for (int c = 0; c < NumChannels; c++) begin
      every_pointer_in_line = every_pointer_in_line &&
          dut_newest_mem_q[c*AgeWidth +: AgeWidth] <= AgeWidth'(SectionOrder) &&
          dut_filled_mem_q[c*(AgeWidth+1) +: AgeWidth+1] <= (AgeWidth + 1)'(SectionOrder + 1);
      if (!accepted_prev_q || 32'(served_q) != c) begin
        other_pointers_still = other_pointers_still &&
            dut_newest_mem_q[c*AgeWidth +: AgeWidth] ==
            newest_mem_prev_q[c*AgeWidth +: AgeWidth] &&
            dut_filled_mem_q[c*(AgeWidth+1) +: AgeWidth+1] ==
            filled_mem_prev_q[c*(AgeWidth+1) +: AgeWidth+1];
      end
    end
  end

  always_comb begin
    // The schedule in the header of rtl/iir_core.sv, cycle by cycle: FSM state, BTC, issue, the
    // write-back pipe and the section count all follow from the cycles since the accepted sample.
    sched_since_bounded: assert (since_q <= SinceWidth'(LatencyCycles));
    sched_busy_exact: assert (busy_o == sched_busy);
    sched_valid_exact: assert (sample_valid_o == (since_q == SinceWidth'(LatencyCycles)));
    if (!sched_busy) begin
      sched_idle_btc: assert (dut_btc_q == '0);
      sched_idle_issue: assert (!dut_issue);
      sched_idle_pipe: assert (dut_wb_pipe_q == '0);
      sched_idle_sections: assert (dut_wb_sec_q == '0 || dut_wb_sec_q == LineWidth'(NumSections));
    end else begin
      sched_state: assert (dut_state_q == (since <= LastIssue ? 2'd1 : 2'd2));
      sched_issue: assert (dut_issue == issues_at(since));
      sched_btc: assert (since > LastIssue ||
                         dut_btc_q == BtcWidth'(section_at(since) * Terms + position_at(since)));
      sched_finish_btc: assert (since <= LastIssue || dut_btc_q == '0);
      sched_pipe: assert (dut_wb_pipe_q == {last_issued_at(since - 3), last_issued_at(since - 2),
                                            last_issued_at(since - 1)});
      sched_sections: assert (dut_wb_sec_q == LineWidth'(written_back_before(since)));
    end
  end

  // 3. The accumulator never wraps. The MAC pipeline follows the schedule: the A register holds
  // the term issued one cycle ago (zero if none), M the product of the term issued two cycles
  // ago (zero if none); a first term restarts the sum at the preload 2^(F-1+L), H_b[0] (position
  // 2M + 1) is added to P >>> L. So P holds the preload plus at most 2M + 1 products (the lo
  // phase), then that sum shifted right by L plus at most 3M + 1 more products, each a
  // ProdWidth-bit number, which fits (checked at elaboration above): the width argument, valid
  // for any sample, history, error and ROM contents.
  // The width bound after n products since the restart.
  function automatic logic signed [63:0] width_bound(int n);
    int hi_terms;
    hi_terms = n - LoTerms;
    if (n <= LoTerms) width_bound = PRELOAD + 64'(n) * PROD_MAX;
    else width_bound = (LO_MAX >>> SplitShift) + 64'sd1 + 64'(hi_terms) * PROD_MAX;
  endfunction

  logic                         m_has_term;
  logic signed [AccWidth-1:0]   acc_base;
  logic signed [AccWidth:0]     acc_exact_sum;
  logic signed [63:0]           acc_bound, p_wide;
  assign m_has_term    = issues_at(since - 2);
  assign acc_terms_d   = dut_mac_first_m_q ? PosWidth'(1) :
                         acc_terms_q + PosWidth'(m_has_term);
  assign acc_base      = dut_mac_first_m_q ? AccWidth'(PRELOAD) :
                         dut_mac_shift_m_q ? dut_mac_p_q >>> SplitShift :
                                             dut_mac_p_q;
  assign acc_exact_sum = (AccWidth + 1)'(acc_base) + (AccWidth + 1)'(dut_mac_m_q);
  assign acc_bound     = width_bound(32'(acc_terms_q));
  assign p_wide        = 64'(dut_mac_p_q);

  always_comb begin
    // The adder's P-bit result is the exact sum of P (or the preload, or P >>> L) and the product.
    acc_no_wrap: assert (acc_exact_sum == (AccWidth + 1)'(dut_mac_p_d));
    // Helper invariants (proven with it): the pipeline contents, the term count and the bound.
    acc_a_idle: assert (issues_at(since - 1) || dut_mac_a_q == '0);
    acc_first_a: assert (dut_mac_first_a_q ==
                         (issues_at(since - 1) && position_at(since - 1) == 0));
    acc_shift_a: assert (dut_mac_shift_a_q ==
                         (issues_at(since - 1) && position_at(since - 1) == ShiftPos));
    acc_m_idle: assert (m_has_term || dut_mac_m_q == '0);
    acc_first_m: assert (dut_mac_first_m_q == (m_has_term && position_at(since - 2) == 0));
    acc_shift_m: assert (dut_mac_shift_m_q == (m_has_term && position_at(since - 2) == ShiftPos));
    acc_terms_bounded: assert (acc_terms_q <= PosWidth'(Terms));
    if (m_has_term && position_at(since - 2) != 0) begin
      acc_terms_before_term: assert (32'(acc_terms_q) == position_at(since - 2));
    end
    acc_within_bound: assert (p_wide <= acc_bound && p_wide >= -acc_bound);
  end

  // 3'. Tighter: the accumulator stays within the generator's bound (coeffs/src/quantize.cpp,
  // docs/fixed_point.md): in the lo phase |P - 2^(F-1+L)| <= sum over the section's lo terms so
  // far of W x 2^(D-1+s); after the shift |P - 2^(F-1)| <= (that sum over all 2M + 1 lo terms
  // >> L) + 1 plus, over the hi and error terms so far, |H| x 2^(D-1+s) and |E| x 2^(F-1) (every
  // operand is a (D+s)-bit word, every error an F-bit one). Here the multiplier's meaning
  // matters: |a * word| <= |word| * |a|max for the word in B.
  logic [CoefWidth-1:0] gen_rom [RomDepth];
  initial $readmemh(RomFile, gen_rom);

  // ROM word (ROM order W_b[0..M], W_a[1..M], H_b[0..M], H_a[1..M], E[1..M]) of the term at issue
  // position p (W_b[1..M], W_a[1..M], W_b[0], H_b[0..M], H_a[1..M], E[1..M]) of section k.
  function automatic int rom_word_of(int k, int p);
    rom_word_of = k * Terms + (p < 2 * SectionOrder ? p + 1 : p == 2 * SectionOrder ? 0 : p);
  endfunction

  // The generator's bound for one product: |word| times the largest operand magnitude.
  function automatic logic signed [63:0] term_bound(logic [CoefWidth-1:0] word, logic error);
    logic signed [63:0] magnitude;
    magnitude  = 64'($signed(word));
    if (magnitude < 0) magnitude = -magnitude;
    term_bound = magnitude <<< (error ? CoefFracBits - 1 : SampleWidth - 1 + FeedbackShift);
  endfunction

  // The centre of the sum after n terms: the preload, or its shifted value after H_b[0].
  function automatic logic signed [63:0] centre_of(int n);
    centre_of = n <= LoTerms ? PRELOAD : PRELOAD_HI;
  endfunction

  // The term bounds in issue order, and their running sums per section: partial[k][n] bounds
  // |P - centre_of(n)| after the first n terms of section k (flat, 64 bits per entry).
  localparam int NumPartials = NumSections * (Terms + 1);
  logic [64*RomDepth-1:0]    bound_of_term;
  logic [64*NumPartials-1:0] partial;
  for (genvar k = 0; k < NumSections; k++) begin : g_section
    for (genvar p = 0; p < Terms; p++) begin : g_term
      assign bound_of_term[64*(k*Terms+p) +: 64] =
        term_bound(gen_rom[rom_word_of(k, p)], p >= ErrPos);
    end
    assign partial[64*(k*(Terms+1)) +: 64] = '0;
    for (genvar n = 1; n <= Terms; n++) begin : g_partial
      if (n == LoTerms + 1) begin : g_shift
        // H_b[0]: the lo sum's bound shifted by L (floor: + 1), then H_b[0]'s product.
        assign partial[64*(k*(Terms+1)+n) +: 64] =
          ($signed(partial[64*(k*(Terms+1)+n-1) +: 64]) >>> SplitShift) + 64'sd1 +
          $signed(bound_of_term[64*(k*Terms+n-1) +: 64]);
      end else begin : g_add
        assign partial[64*(k*(Terms+1)+n) +: 64] =
          $signed(partial[64*(k*(Terms+1)+n-1) +: 64]) +
          $signed(bound_of_term[64*(k*Terms+n-1) +: 64]);
      end
    end
  end

  logic                      a_has_term, a_error;
  logic [CoefWidth-1:0]      a_word;
  logic signed [63:0]        m_bound, gen_bound, gen_centre, gen_worst, m_wide, a_wide;
  logic [LineWidth-1:0]      gen_section_q, gen_section_d;  // section of the sum in P
  assign a_has_term    = issues_at(since - 1);
  assign a_word        = gen_rom[rom_word_of(section_at(since - 1), position_at(since - 1))];
  assign a_error       = position_at(since - 1) >= ErrPos;
  assign m_bound       = $signed(bound_of_term[64*(section_at(since - 2) * Terms +
                                                  position_at(since - 2)) +: 64]);
  assign gen_section_d = m_has_term ? LineWidth'(section_at(since - 2)) : gen_section_q;
  // Until the first restart after reset P is 0: within the preload of the preload.
  assign gen_bound     = acc_terms_q == '0 ? PRELOAD :
                         $signed(partial[64*(32'(gen_section_q)*(Terms+1)+32'(acc_terms_q)) +: 64]);
  assign gen_centre    = centre_of(32'(acc_terms_q));
  assign m_wide        = 64'(dut_mac_m_q);
  assign a_wide        = 64'(dut_mac_a_q);

  // The generator's worst case: the largest P of either phase of any section (each phase's bound
  // grows with its terms: its last term's is its largest).
  always_comb begin
    gen_worst = '0;
    for (int k = 0; k < NumSections; k++) begin
      if (PRELOAD + $signed(partial[64*(k*(Terms+1)+LoTerms) +: 64]) > gen_worst) begin
        gen_worst = PRELOAD + $signed(partial[64*(k*(Terms+1)+LoTerms) +: 64]);
      end
      if (PRELOAD_HI + $signed(partial[64*(k*(Terms+1)+Terms) +: 64]) > gen_worst) begin
        gen_worst = PRELOAD_HI + $signed(partial[64*(k*(Terms+1)+Terms) +: 64]);
      end
    end
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) gen_section_q <= '0;
    else         gen_section_q <= gen_section_d;
  end

  always_comb begin
    gen_worst_fits: assert (gen_worst <= ACC_MAX);
    gen_within_bound: assert (p_wide - gen_centre <= gen_bound && gen_centre - p_wide <= gen_bound);
    gen_section_in_range: assert (gen_section_q < LineWidth'(NumSections));
    if (a_has_term) begin
      // B holds the term's ROM word; A an F-bit error for an E word.
      gen_b_is_rom_word: assert (dut_mac_b_q == $signed(a_word));
      gen_a_error: assert (!a_error || (a_wide < (64'sd1 <<< (CoefFracBits - 1)) &&
                                        a_wide >= -(64'sd1 <<< (CoefFracBits - 1))));
    end
    if (m_has_term) begin
      gen_m_within_term_bound: assert (m_wide <= m_bound && m_wide >= -m_bound);
      if (position_at(since - 2) != 0) begin
        gen_section_of_sum: assert (32'(gen_section_q) == section_at(since - 2));
      end
    end
  end

endmodule
