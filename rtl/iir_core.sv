// SPDX-License-Identifier: MIT
// IIR filter core: a cascade of sections of one order, all computed on one multiply-accumulate
// unit (one DSP48E1), sequenced by an FSM over a coefficient ROM and the sample history.
//
// Fixed-point contract (docs/fixed_point.md; the same paragraph heads model/iir_core.h).
// D = SampleWidth, C = CoefWidth, P = AccWidth, Fb = NumFracBits, Fa = CoefFracBits,
// s = FeedbackShift = Fb - Fa, K = NumSections, M = SectionOrder.
// - Formats: samples in, out and between sections are Q1.(D-1) (Q1.15 by default). The ROM holds
//   C-bit words: b as Q(C-Fb).Fb, the negated denominator -a as Q(C-Fa).Fa. Feedback samples enter
//   the multiplier as y << s (D + s <= 25 bits, the DSP48E1 A port), so every product is
//   Q.(D-1+Fb) in D+s+C bits, summed in a P-bit two's complement accumulator that wraps like the
//   DSP48E1 P register (the generator proves that legal samples never make it wrap).
// - Rounding: round half up. The accumulator starts each section at 2^(Fb-1) and the sum is
//   shifted arithmetically right by Fb.
// - Saturation: every section's output is clipped to [-2^(D-1), 2^(D-1) - 1] before it enters the
//   history and the next section; a clip sets the sticky saturation_o.
// - ROM order: section 0 first; within a section b[0..M], then -a[1..M]. Load registers: K + 1
//   lines of M + 1 samples, newest first; line 0 is the input x[n..n-M], line k + 1 the output of
//   section k (the input of section k + 1). The bus target counter (BTC) walks the ROM and the
//   matching load registers with one count.
// - Timing: a section takes 2M + 1 MAC cycles plus 3 cycles of MAC latency. From the cycle in
//   which sample_valid_i is accepted to the cycle in which sample_valid_o is high:
//   LatencyCycles = K * (2M + 4) + 1. A new sample is accepted in the cycle sample_valid_o is
//   high, so CyclesPerSample = LatencyCycles too.
//
// Flags: sample_valid_i while busy_o is high drops that sample (the history is untouched) and sets
// the sticky overrun_o. Sticky flags clear on reset or with flag_clear_i; a flag event in the same
// cycle as flag_clear_i wins, so no event is lost.
`default_nettype none

module iir_core #(
  // $readmemh image of the coefficient ROM: the coeffs.mem beside the iir_coeffs_pkg.sv the core
  // is built with.
  parameter RomFile = "coeffs.mem"
) (
  input  logic                                        clk_i,
  input  logic                                        rst_ni,          // synchronous, active low
  input  logic signed [iir_coeffs_pkg::SampleWidth-1:0] sample_i,
  input  logic                                        sample_valid_i,  // EN: one cycle per sample
  output logic signed [iir_coeffs_pkg::SampleWidth-1:0] sample_o,
  output logic                                        sample_valid_o,  // one cycle per output
  output logic                                        busy_o,          // sample_valid_i is dropped
  output logic                                        overrun_o,       // sticky: a sample dropped
  output logic                                        saturation_o,    // sticky: an output clipped
  input  logic                                        flag_clear_i     // clears the sticky flags
);

  // Parameters //
  localparam int FilterOrder   = iir_coeffs_pkg::FilterOrder;
  localparam int NumSections   = iir_coeffs_pkg::NumSections;
  localparam int SectionOrder  = iir_coeffs_pkg::SectionOrder;
  localparam int SampleWidth   = iir_coeffs_pkg::SampleWidth;
  localparam int CoefWidth     = iir_coeffs_pkg::CoefWidth;
  localparam int CoefFracBits  = iir_coeffs_pkg::CoefFracBits;
  localparam int NumFracBits   = iir_coeffs_pkg::NumFracBits;
  localparam int FeedbackShift = iir_coeffs_pkg::FeedbackShift;
  localparam int AccWidth      = iir_coeffs_pkg::AccWidth;
  localparam int RomDepth      = iir_coeffs_pkg::RomDepth;

  localparam int Terms         = 2 * SectionOrder + 1;              // MACs per section
  localparam int LrLine        = SectionOrder + 1;                  // samples per history line
  localparam int LrDepth       = (NumSections + 1) * LrLine;
  localparam int AWidth        = SampleWidth + FeedbackShift;       // multiplier A operand
  localparam int MacLatency    = 3;                                 // iir_mac: A/B, M, P
  localparam int LatencyCycles = NumSections * (Terms + MacLatency) + 1;
  localparam int BtcWidth      = RomDepth > 1 ? $clog2(RomDepth) : 1;
  localparam int SecWidth      = NumSections > 1 ? $clog2(NumSections) : 1;

  localparam logic signed [SampleWidth-1:0] SAMPLE_MAX = {1'b0, {(SampleWidth - 1){1'b1}}};
  localparam logic signed [SampleWidth-1:0] SAMPLE_MIN = {1'b1, {(SampleWidth - 1){1'b0}}};

  // Elaboration checks: a set that breaks the contract must not build //
  if (RomDepth != NumSections * Terms) begin : g_bad_rom_depth
    $error("iir_core: RomDepth must equal NumSections * (2 * SectionOrder + 1)");
  end
  if (FilterOrder > NumSections * SectionOrder) begin : g_bad_order
    $error("iir_core: FilterOrder exceeds NumSections * SectionOrder");
  end
  if (FeedbackShift != NumFracBits - CoefFracBits || FeedbackShift < 0) begin : g_bad_shift
    $error("iir_core: FeedbackShift must equal NumFracBits - CoefFracBits >= 0");
  end
  if (NumFracBits < 1 || AccWidth < NumFracBits + SampleWidth) begin : g_bad_acc
    $error("iir_core: need 1 <= NumFracBits and NumFracBits + SampleWidth <= AccWidth");
  end
  if (AWidth + CoefWidth > AccWidth) begin : g_bad_product
    $error("iir_core: the product (SampleWidth + FeedbackShift + CoefWidth) exceeds AccWidth");
  end

  // Lowest bit of the sample `age` samples old (0 <= age <= M) in load-register line `l`.
  function automatic int lr_bit(int l, int age);
    lr_bit = (l * LrLine + age) * SampleWidth;  // Yosys 0.23 has no `return`
  endfunction

  typedef enum logic [1:0] {
    StIdle  = 2'd0,  // wait for EN
    StMac   = 2'd1,  // issue one term per cycle, BTC counting
    StDrain = 2'd2   // let the MAC latency pass, then round, saturate and write back
  } state_e;

  state_e                                state_q, state_d;
  logic [BtcWidth-1:0]                   btc_q, btc_d;      // bus target counter
  logic [SecWidth-1:0]                   sec_q, sec_d;      // section being computed
  logic [1:0]                            drain_q, drain_d;  // cycles spent in StDrain
  // Load registers: one flat vector, because Yosys 0.23 does not parse multi-dimensional packed
  // arrays; lr_bit() gives the position of a sample. Only constant positions are used: a computed
  // index would cost a barrel shifter.
  logic [LrDepth*SampleWidth-1:0]        lr_q, lr_d;
  logic signed [SampleWidth-1:0]         out_q, out_d;
  logic                                  valid_q, valid_d;
  logic                                  overrun_q, overrun_d;
  logic                                  saturation_q, saturation_d;

  // Coefficient ROM //
  logic [CoefWidth-1:0] rom [RomDepth];
  initial $readmemh(RomFile, rom);

  // BTC decode: the ROM word's role and the load register it multiplies //
  logic                          term_first, term_last, term_feedback;
  logic signed [SampleWidth-1:0] lr_sample;
  always_comb begin
    term_first    = 1'b0;
    term_last     = 1'b0;
    term_feedback = 1'b0;
    lr_sample     = '0;
    for (int k = 0; k < NumSections; k++) begin
      for (int i = 0; i < Terms; i++) begin
        if (btc_q == BtcWidth'(k * Terms + i)) begin
          term_first    = (i == 0);
          term_last     = (i == Terms - 1);
          term_feedback = (i > SectionOrder);
          // b[i] multiplies x_k[n-i] (line k); -a[j], j = i - M, multiplies y_k[n-j] (line k + 1).
          if (i <= SectionOrder) lr_sample = $signed(lr_q[lr_bit(k, i) +: SampleWidth]);
          else lr_sample = $signed(lr_q[lr_bit(k + 1, i - SectionOrder) +: SampleWidth]);
        end
      end
    end
  end

  // Operands //
  logic                          issue;
  logic signed [AWidth-1:0]      mac_a;
  logic signed [CoefWidth-1:0]   mac_b;
  logic signed [AccWidth-1:0]    mac_p;

  // The feedback shift gives the numerator s more fractional bits at no DSP cost (A port <= 25).
  assign mac_a = !issue        ? '0 :
                 term_feedback ? AWidth'(lr_sample) <<< FeedbackShift :
                                 AWidth'(lr_sample);
  assign mac_b = $signed(rom[btc_q]);

  iir_mac #(
    .AWidth    (AWidth),
    .BWidth    (CoefWidth),
    .AccWidth  (AccWidth),
    .PreloadBit(NumFracBits - 1)
  ) u_mac (
    .clk_i,
    .rst_ni,
    .a_i    (mac_a),
    .b_i    (mac_b),
    .first_i(issue & term_first),
    .p_o    (mac_p)
  );

  // Round (preloaded) and saturate //
  // The sum fits the sample format when every bit above the sample's sign bit equals it.
  logic [AccWidth-NumFracBits-SampleWidth:0] acc_top;
  logic                                      clip;
  logic signed [SampleWidth-1:0]             section_y;

  assign acc_top   = mac_p[AccWidth-1:NumFracBits+SampleWidth-1];
  assign clip      = !((&acc_top) || !(|acc_top));
  assign section_y = !clip     ? mac_p[NumFracBits+SampleWidth-1:NumFracBits] :
                     mac_p[AccWidth-1] ? SAMPLE_MIN : SAMPLE_MAX;

  // FSM //
  logic writeback;
  always_comb begin
    state_d   = state_q;
    btc_d     = btc_q;
    sec_d     = sec_q;
    drain_d   = drain_q;
    lr_d      = lr_q;
    out_d     = out_q;
    valid_d   = 1'b0;
    issue     = 1'b0;
    writeback = 1'b0;

    unique case (state_q)
      StIdle: begin
        if (sample_valid_i) begin
          // EN: the history moves one place older in every line; x[n] enters line 0.
          for (int l = 0; l <= NumSections; l++) begin
            for (int i = SectionOrder; i > 0; i--) begin
              lr_d[lr_bit(l, i) +: SampleWidth] = lr_q[lr_bit(l, i - 1) +: SampleWidth];
            end
          end
          lr_d[lr_bit(0, 0) +: SampleWidth] = sample_i;
          btc_d   = '0;
          sec_d   = '0;
          state_d = StMac;
        end
      end
      StMac: begin
        issue = 1'b1;
        btc_d = (btc_q == BtcWidth'(RomDepth - 1)) ? '0 : btc_q + 1'b1;
        if (term_last) begin
          drain_d = '0;
          state_d = StDrain;
        end
      end
      StDrain: begin
        if (drain_q == 2'(MacLatency - 1)) begin
          // The last term of the section has reached the accumulator.
          writeback        = 1'b1;
          // The section's output becomes the newest entry of the next line.
          for (int k = 0; k < NumSections; k++) begin
            if (sec_q == SecWidth'(k)) lr_d[lr_bit(k + 1, 0) +: SampleWidth] = section_y;
          end
          if (sec_q == SecWidth'(NumSections - 1)) begin
            out_d   = section_y;
            valid_d = 1'b1;
            state_d = StIdle;
          end else begin
            sec_d   = sec_q + 1'b1;
            state_d = StMac;
          end
        end else begin
          drain_d = drain_q + 1'b1;
        end
      end
      default: state_d = StIdle;
    endcase
  end

  // Sticky flags //
  assign overrun_d    = (overrun_q & ~flag_clear_i) | (sample_valid_i & (state_q != StIdle));
  assign saturation_d = (saturation_q & ~flag_clear_i) | (writeback & clip);

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      state_q      <= StIdle;
      btc_q        <= '0;
      sec_q        <= '0;
      drain_q      <= '0;
      lr_q         <= '0;
      out_q        <= '0;
      valid_q      <= 1'b0;
      overrun_q    <= 1'b0;
      saturation_q <= 1'b0;
    end else begin
      state_q      <= state_d;
      btc_q        <= btc_d;
      sec_q        <= sec_d;
      drain_q      <= drain_d;
      lr_q         <= lr_d;
      out_q        <= out_d;
      valid_q      <= valid_d;
      overrun_q    <= overrun_d;
      saturation_q <= saturation_d;
    end
  end

  assign sample_o       = out_q;
  assign sample_valid_o = valid_q;
  assign busy_o         = (state_q != StIdle);
  assign overrun_o      = overrun_q;
  assign saturation_o   = saturation_q;

  // Assertions //
`ifndef SYNTHESIS
  // The BTC stays on a ROM word of the current section while terms are issued.
  always @(posedge clk_i) begin
    if (rst_ni && state_q == StMac) begin
      assert (32'(btc_q) >= 32'(sec_q) * Terms && 32'(btc_q) < (32'(sec_q) + 1) * Terms)
      else $error("iir_core: BTC %0d outside section %0d", btc_q, sec_q);
    end
  end

  // The result is only read once the section's last product has left the MAC pipeline.
  always @(posedge clk_i) begin
    if (rst_ni && writeback) begin
      assert (!issue) else $error("iir_core: write-back while terms are still being issued");
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
