// SPDX-License-Identifier: MIT
// Q1.15 sample word -> clearance in mm with two decimals, as four display digit codes.
//
// mm = 6 + 8 * word / 2^15 (host/engines/sample_scaling.h), so in hundredths of a millimetre
// h = 600 + 25 * word / 2^10, rounded half up: h = floor((614400 + 25 * word + 512) / 1024),
// an exact integer computation (no float anywhere). word in [-32768, 32767] gives h in
// [-200, 1400], i.e. -2.00 to 14.00 mm: "-1.99", " 9.87", "14.00" (the decimal point is the one
// of the second digit from the left). The magnitude is registered and converted to BCD one bit
// per cycle, so no path is long at 100 MHz; the digits lag word_i by at most 26 cycles.
`default_nettype none

module clearance_display (
  input  logic               clk_i,
  input  logic               rst_ni,    // synchronous, active low
  input  logic signed [15:0] word_i,
  output logic [19:0]        digits_o,  // 4 x 5-bit codes, leftmost in [19:15]; see seven_seg
  output logic [3:0]         dp_o       // decimal points, leftmost in [3]
);

  localparam logic [4:0] CODE_BLANK = 5'h10;
  localparam logic [4:0] CODE_MINUS = 5'h11;

  logic signed [22:0] scaled;    // 614400 + 25 * word + 512: within +-2^22
  logic signed [12:0] hundredths;
  logic               negative, negative_q;
  logic [10:0]        magnitude, magnitude_q;  // |h| <= 1400
  logic [15:0]        bcd;        // bcd_q with 3 added to every digit >= 5
  logic [19:0]        digits_d, digits_q;

  logic signed [22:0] word;
  assign word       = 23'(word_i);
  // 25 = 16 + 8 + 1 as shifts and adds: a constant multiply would take a DSP48E1 of its own.
  assign scaled     = 23'sd614912 + (word <<< 4) + (word <<< 3) + word;
  assign hundredths = scaled[22:10];  // arithmetic shift: floor division by 1024
  assign negative   = hundredths[12];
  assign magnitude  = negative ? 11'(-hundredths) : hundredths[10:0];

  // Double dabble, one bit per cycle (a combinational one is about 20 cells deep): a conversion
  // takes 12 cycles (load, 11 shifts) and they run back to back, so the digits follow word_i
  // within 26 cycles. Step 0 loads the magnitude and publishes the previous result.
  logic [3:0]  step_q, step_d;
  logic [10:0] bits_q, bits_d;
  logic [15:0] bcd_q, bcd_d;
  logic        conv_negative_q, conv_negative_d;

  always_comb begin
    bcd = bcd_q;
    for (int d = 0; d < 4; d++) begin
      if (bcd[4*d +: 4] >= 4'd5) bcd[4*d +: 4] = bcd[4*d +: 4] + 4'd3;
    end
  end

  always_comb begin
    digits_d        = digits_q;
    conv_negative_d = conv_negative_q;
    if (step_q == 4'd0) begin
      bits_d          = magnitude_q;
      bcd_d           = '0;
      conv_negative_d = negative_q;
      step_d          = 4'd1;
      digits_d[14:10] = {1'b0, bcd_q[11:8]};
      digits_d[9:5]   = {1'b0, bcd_q[7:4]};
      digits_d[4:0]   = {1'b0, bcd_q[3:0]};
      if (conv_negative_q)         digits_d[19:15] = CODE_MINUS;  // |h| <= 200: no thousands
      else if (bcd_q[15:12] == '0) digits_d[19:15] = CODE_BLANK;
      else                         digits_d[19:15] = {1'b0, bcd_q[15:12]};
    end else begin
      bits_d = {bits_q[9:0], 1'b0};
      bcd_d  = {bcd[14:0], bits_q[10]};
      step_d = step_q == 4'd11 ? 4'd0 : step_q + 4'd1;
    end
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      negative_q      <= 1'b0;
      magnitude_q     <= 11'd600;
      step_q          <= '0;
      bits_q          <= '0;
      bcd_q           <= 16'h0600;  // word 0: " 6.00"
      conv_negative_q <= 1'b0;
      digits_q        <= {CODE_BLANK, 5'd6, 5'd0, 5'd0};
    end else begin
      negative_q      <= negative;
      magnitude_q     <= magnitude;
      step_q          <= step_d;
      bits_q          <= bits_d;
      bcd_q           <= bcd_d;
      conv_negative_q <= conv_negative_d;
      digits_q        <= digits_d;
    end
  end

  assign digits_o = digits_q;
  assign dp_o     = 4'b0100;

  // The bits below 2^10 are the remainder of the floor division.
  logic unused_remainder;
  assign unused_remainder = ^scaled[9:0];

endmodule
