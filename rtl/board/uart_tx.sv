// SPDX-License-Identifier: MIT
// UART transmitter, 8N1, LSB first: takes a byte when ready_o is high.
`default_nettype none

module uart_tx #(
  // Clock cycles per bit: 868 for 115200 baud at 100 MHz; >= 1.
  parameter int ClksPerBit = 868
) (
  input  logic       clk_i,
  input  logic       rst_ni,      // synchronous, active low
  input  logic [7:0] data_i,
  input  logic       data_valid_i,
  output logic       ready_o,     // idle: data_valid_i now starts a frame
  output logic       tx_o         // idle high
);

  localparam int CntWidth = $clog2(ClksPerBit + 1);
  localparam logic [CntWidth-1:0] FULL_BIT = CntWidth'(ClksPerBit - 1);

  // Start bit, 8 data bits, stop bit: shifted out LSB first; the register idles at all ones.
  logic [9:0]          shift_q, shift_d;
  logic [3:0]          left_q, left_d;   // bits still to send
  logic [CntWidth-1:0] cnt_q, cnt_d;

  always_comb begin
    shift_d = shift_q;
    left_d  = left_q;
    cnt_d   = cnt_q;
    if (left_q == '0) begin
      if (data_valid_i) begin
        shift_d = {1'b1, data_i, 1'b0};
        left_d  = 4'd10;
        cnt_d   = FULL_BIT;
      end
    end else if (cnt_q != '0) begin
      cnt_d = cnt_q - 1'b1;
    end else begin
      shift_d = {1'b1, shift_q[9:1]};
      left_d  = left_q - 1'b1;
      cnt_d   = FULL_BIT;
    end
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      shift_q <= '1;
      left_q  <= '0;
      cnt_q   <= '0;
    end else begin
      shift_q <= shift_d;
      left_q  <= left_d;
      cnt_q   <= cnt_d;
    end
  end

  assign ready_o = left_q == '0;
  assign tx_o    = shift_q[0];

endmodule
