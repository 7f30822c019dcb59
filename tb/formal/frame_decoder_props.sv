// SPDX-License-Identifier: MIT
// Formal wrapper of the board's receive path, uart_rx (u_rx) into frame_decoder (the DUT, `dut`):
// a frame is reported valid only when it is the last six bytes received, none of them used by
// an earlier frame, starting with SYNC or CMD_SYNC and ending with the CRC-8 of the middle four
// (docs/formal.md, docs/board.md). Proven by tb/formal/prove.sh with Yosys.
//
// The serial line rx_i is free in every cycle (any bit pattern, glitches, bad stop bits); prove.sh
// only holds rst_ni low in the first cycle. The checks are immediate assertions in always_comb
// blocks: each holds in every cycle. Labels start with crc_ (the property) or rx_ (a helper
// invariant of the receiver, proven with it).
`default_nettype none

module frame_decoder_props #(
  parameter int ClksPerBit = 868  // the board's default (100 MHz, 115200 baud)
) (
  input logic clk_i,
  input logic rst_ni,
  input logic rx_i
);

  localparam int         FrameBytes = 6;
  localparam logic [7:0] SYNC       = 8'hA5;
  localparam logic [7:0] CMD_SYNC   = 8'h5A;

  logic [7:0]  rx_byte;
  logic        rx_byte_valid;
  logic [7:0]  seq_o, channel_o;
  logic [15:0] sample_o;
  logic        frame_valid_o, command_o;
  // Stop-bit errors and discards are counted on the board; no property here is about them.
  /* verilator lint_off UNUSEDSIGNAL */
  logic        frame_err, discard_o;
  /* verilator lint_on UNUSEDSIGNAL */

  uart_rx #(.ClksPerBit(ClksPerBit)) u_rx (
    .clk_i,
    .rst_ni,
    .rx_i,
    .data_o      (rx_byte),
    .data_valid_o(rx_byte_valid),
    .frame_err_o (frame_err)
  );

  frame_decoder dut (
    .clk_i,
    .rst_ni,
    .byte_i      (rx_byte),
    .byte_valid_i(rx_byte_valid),
    .seq_o,
    .channel_o,
    .sample_o,
    .frame_valid_o,
    .command_o,
    .discard_o
  );

  // Internal signals //
  // Yosys 0.23 has no hierarchical references: under Yosys these wires stay undriven here and
  // prove.sh connects each one to the flattened signal named in its `assign` line below. Verilator
  // reads the references as written (and checks their names and widths).
  logic [8*FrameBytes-1:0] dut_window_q;
  logic [2:0]              dut_fill_q;
  logic                    dut_fresh_q;
  logic [1:0]              u_rx_state_q;
`ifndef YOSYS
  assign dut_window_q = dut.window_q;
  assign dut_fill_q   = dut.fill_q;
  assign dut_fresh_q  = dut.fresh_q;
  assign u_rx_state_q = u_rx.state_q;
`endif

  // Shadow model of the byte stream //
  // The last six bytes the UART delivered (shadow_q[47:40] the oldest), how many of them arrived
  // since the last reported frame (a reported frame uses its six bytes up), and whether one
  // arrived in the previous cycle.
  logic [8*FrameBytes-1:0] shadow_q, shadow_d;
  logic [2:0]              unused_q, unused_d;
  logic                    arrived_q;
  assign shadow_d = rx_byte_valid ? {shadow_q[8*FrameBytes-9:0], rx_byte} : shadow_q;
  always_comb begin
    unused_d = unused_q;
    if (frame_valid_o) unused_d = '0;
    if (rx_byte_valid && unused_d != 3'(FrameBytes)) unused_d = unused_d + 1'b1;
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      shadow_q  <= '0;
      unused_q  <= '0;
      arrived_q <= 1'b0;
    end else begin
      shadow_q  <= shadow_d;
      unused_q  <= unused_d;
      arrived_q <= rx_byte_valid;
    end
  end

  // CRC-8/SMBUS by its definition, independent of crc8.sv: the remainder of M(x) * x^8 divided by
  // G(x) = x^8 + x^2 + x + 1 (0x107), M the four bytes MSB first, no initial value, no final XOR.
  function automatic logic [7:0] crc8_by_division(logic [31:0] message);
    logic [39:0] rem;
    rem = {message, 8'h00};
    for (int i = 39; i >= 8; i--) begin
      if (rem[i]) rem = rem ^ (40'h107 << (i - 8));
    end
    crc8_by_division = rem[7:0];
  endfunction

  always_comb begin
    if (frame_valid_o) begin
      // The frame is the last six bytes received, none of them part of an earlier frame, and
      // arrived with the last one in the previous cycle.
      crc_frame_is_fresh: assert (unused_q == 3'(FrameBytes) && arrived_q);
      crc_frame_starts_with_sync: assert (shadow_q[47:40] == SYNC || shadow_q[47:40] == CMD_SYNC);
      // Its last byte is the CRC-8 of the four bytes between.
      crc_matches: assert (shadow_q[7:0] == crc8_by_division(shadow_q[39:8]));
      // The decoder reports those bytes.
      crc_reports_frame: assert (seq_o == shadow_q[39:32] && channel_o == shadow_q[31:24] &&
                                 sample_o == shadow_q[23:8] &&
                                 command_o == (shadow_q[47:40] == CMD_SYNC));
      // No byte lands in the cycle of a reported frame (it would be lost).
      crc_no_byte_during_frame: assert (!rx_byte_valid);
    end
    // Helper invariants (proven with them): the decoder's window is the shadow, its fill count
    // the unused bytes, its fresh bit the arrival; the UART goes idle after a byte.
    crc_window_is_shadow: assert (dut_window_q == shadow_q);
    crc_fill_is_unused: assert (dut_fill_q == unused_q);
    crc_fresh_is_arrived: assert (dut_fresh_q == arrived_q);
    rx_idle_after_byte: assert (!rx_byte_valid || u_rx_state_q == 2'd0);
  end

endmodule
