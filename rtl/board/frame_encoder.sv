// SPDX-License-Identifier: MIT
// Board -> host frame encoder: SYNC, SEQ, CHANNEL, OUT_HI, OUT_LO, STATUS, CRC-8(SEQ..STATUS),
// handed byte by byte to the UART transmitter (docs/board.md).
`default_nettype none

module frame_encoder (
  input  logic        clk_i,
  input  logic        rst_ni,        // synchronous, active low
  input  logic [7:0]  seq_i,
  input  logic [7:0]  channel_i,
  input  logic [15:0] sample_i,
  input  logic [7:0]  status_i,
  input  logic        send_i,        // one cycle; taken only while busy_o is low
  output logic        busy_o,        // a frame is being sent (until its last byte has left)
  output logic [7:0]  tx_data_o,
  output logic        tx_valid_o,
  input  logic        tx_ready_i
);

  localparam logic [7:0] SYNC = 8'hA5;
  localparam int FrameBytes = 7;

  logic [8*FrameBytes-1:0] frame_q, frame_d;  // next byte to send in [55:48]
  logic [2:0]              left_q, left_d;    // bytes still to hand over
  logic                    draining_q, draining_d;  // last byte handed over, not yet sent
  logic [7:0]              crc;

  crc8 #(.NumBytes(5)) u_crc (
    .data_i({seq_i, channel_i, sample_i, status_i}),
    .crc_o (crc)
  );

  always_comb begin
    frame_d    = frame_q;
    left_d     = left_q;
    draining_d = draining_q;
    if (left_q == '0 && !draining_q) begin
      if (send_i) begin
        frame_d = {SYNC, seq_i, channel_i, sample_i, status_i, crc};
        left_d  = 3'(FrameBytes);
      end
    end else if (left_q != '0) begin
      if (tx_ready_i) begin
        frame_d = {frame_q[8*FrameBytes-9:0], 8'h00};
        left_d  = left_q - 1'b1;
        if (left_q == 3'd1) draining_d = 1'b1;
      end
    end else if (tx_ready_i) begin
      draining_d = 1'b0;  // the transmitter is idle again: the last stop bit has gone out
    end
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      frame_q    <= '0;
      left_q     <= '0;
      draining_q <= 1'b0;
    end else begin
      frame_q    <= frame_d;
      left_q     <= left_d;
      draining_q <= draining_d;
    end
  end

  assign busy_o     = left_q != '0 || draining_q;
  assign tx_data_o  = frame_q[8*FrameBytes-1 -: 8];
  assign tx_valid_o = left_q != '0;

endmodule
