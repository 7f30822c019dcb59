// SPDX-License-Identifier: MIT
// Q1.15 sample word -> clearance in mm with two decimals, as four display digit codes.
//
// mm = 6 + 8 * word / 2^15 (host/src/sample_scaling.h), so in hundredths of a millimetre
// h = 600 + 25 * word / 2^10, rounded half up: h = floor((614400 + 25 * word + 512) / 1024),
// an exact integer computation (no float anywhere). word in [-32768, 32767] gives h in
// [-200, 1400], i.e. -2.00 to 14.00 mm: "-1.99", " 9.87", "14.00" (the decimal point is the one
// of the second digit from the left).
`default_nettype none

module clearance_display (
  input  logic signed [15:0] word_i,
  output logic [19:0]        digits_o,  // 4 x 5-bit codes, leftmost in [19:15]; see seven_seg
  output logic [3:0]         dp_o       // decimal points, leftmost in [3]
);

  localparam logic [4:0] CODE_BLANK = 5'h10;
  localparam logic [4:0] CODE_MINUS = 5'h11;

  logic signed [22:0] scaled;    // 614400 + 25 * word + 512: within +-2^22
  logic signed [12:0] hundredths;
  logic               negative;
  logic [10:0]        magnitude;  // |h| <= 1400
  logic [15:0]        bcd;

  logic signed [22:0] word;
  assign word       = 23'(word_i);
  // 25 = 16 + 8 + 1 as shifts and adds: a constant multiply would take a DSP48E1 of its own.
  assign scaled     = 23'sd614912 + (word <<< 4) + (word <<< 3) + word;
  assign hundredths = scaled[22:10];  // arithmetic shift: floor division by 1024
  assign negative   = hundredths[12];
  assign magnitude  = negative ? 11'(-hundredths) : hundredths[10:0];

  // Double dabble: binary to four BCD digits.
  always_comb begin
    bcd = '0;
    for (int i = 10; i >= 0; i--) begin
      for (int d = 0; d < 4; d++) begin
        if (bcd[4*d +: 4] >= 4'd5) bcd[4*d +: 4] = bcd[4*d +: 4] + 4'd3;
      end
      bcd = {bcd[14:0], magnitude[i]};
    end
  end

  always_comb begin
    digits_o[14:10] = {1'b0, bcd[11:8]};
    digits_o[9:5]   = {1'b0, bcd[7:4]};
    digits_o[4:0]   = {1'b0, bcd[3:0]};
    if (negative)              digits_o[19:15] = CODE_MINUS;   // |h| <= 200: no thousands
    else if (bcd[15:12] == '0) digits_o[19:15] = CODE_BLANK;
    else                       digits_o[19:15] = {1'b0, bcd[15:12]};
  end
  assign dp_o = 4'b0100;

  // The bits below 2^10 are the remainder of the floor division.
  logic unused_remainder;
  assign unused_remainder = ^scaled[9:0];

endmodule
