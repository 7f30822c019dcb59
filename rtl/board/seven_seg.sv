// SPDX-License-Identifier: MIT
// Four-digit multiplexed seven-segment driver for the Basys-3 (segments and anodes active low).
`default_nettype none

module seven_seg #(
  // Each digit is lit for 2^(RefreshBits-2) cycles: 18 gives 655 us at 100 MHz, a 381 Hz frame.
  parameter int RefreshBits = 18
) (
  input  logic        clk_i,
  input  logic        rst_ni,    // synchronous, active low
  input  logic [19:0] digits_i,  // 4 x 5-bit codes, leftmost in [19:15]: 0-15 hex, 16 blank, 17 '-'
  input  logic [3:0]  dp_i,      // decimal points, leftmost in [3]
  output logic [6:0]  seg_no,    // CA..CG in [0]..[6], active low
  output logic        dp_no,     // active low
  output logic [3:0]  an_no      // an_no[3] is the leftmost digit, active low
);

  logic [RefreshBits-1:0] cnt_q, cnt_d;
  logic [1:0]             sel;
  logic [4:0]             code;
  logic [6:0]             seg;   // active high, CA in [0]

  assign cnt_d = cnt_q + 1'b1;
  assign sel   = cnt_q[RefreshBits-1 -: 2];
  assign code  = digits_i[5*sel +: 5];

  always_comb begin
    unique case (code)
      5'h00: seg = 7'b0111111;
      5'h01: seg = 7'b0000110;
      5'h02: seg = 7'b1011011;
      5'h03: seg = 7'b1001111;
      5'h04: seg = 7'b1100110;
      5'h05: seg = 7'b1101101;
      5'h06: seg = 7'b1111101;
      5'h07: seg = 7'b0000111;
      5'h08: seg = 7'b1111111;
      5'h09: seg = 7'b1101111;
      5'h0a: seg = 7'b1110111;
      5'h0b: seg = 7'b1111100;
      5'h0c: seg = 7'b0111001;
      5'h0d: seg = 7'b1011110;
      5'h0e: seg = 7'b1111001;
      5'h0f: seg = 7'b1110001;
      5'h11: seg = 7'b1000000;
      default: seg = 7'b0000000;  // blank
    endcase
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) cnt_q <= '0;
    else         cnt_q <= cnt_d;
  end

  assign seg_no = ~seg;
  assign dp_no  = ~dp_i[sel];
  assign an_no  = ~(4'b0001 << sel);

endmodule
