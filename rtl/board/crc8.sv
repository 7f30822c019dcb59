// SPDX-License-Identifier: MIT
// CRC-8 (polynomial x^8 + x^2 + x + 1 = 0x07, initial value 0, MSB first, no final XOR; the
// "CRC-8/SMBUS" of the CRC catalogue) over NumBytes bytes, combinational.
// It detects every 1-, 2- and odd-bit error and every burst up to 8 bits in the link's frames.
`default_nettype none

module crc8 #(
  parameter int NumBytes = 3
) (
  input  logic [8*NumBytes-1:0] data_i,  // first byte in the most significant position
  output logic [7:0]            crc_o
);

  logic [7:0] crc;
  always_comb begin
    crc = 8'h00;
    for (int i = 8 * NumBytes - 1; i >= 0; i--) begin
      if (crc[7] ^ data_i[i]) crc = {crc[6:0], 1'b0} ^ 8'h07;
      else                    crc = {crc[6:0], 1'b0};
    end
  end
  assign crc_o = crc;

endmodule
