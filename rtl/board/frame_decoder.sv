// SPDX-License-Identifier: MIT
// Host -> board frame decoder: a sliding window over the last six received bytes, accepted when
// it reads SYNC, SEQ, CHANNEL, SAMPLE_HI, SAMPLE_LO, CRC-8(SEQ, CHANNEL, SAMPLE_HI, SAMPLE_LO)
// (docs/board.md). A command frame has CMD_SYNC in place of SYNC and a 16-bit command in place of
// the sample.
//
// The window is checked after every byte, so the decoder resynchronises on the first intact
// frame after a lost, extra or corrupted byte. An accepted frame empties the window (its bytes
// are never reused); every byte that leaves the window without being part of an accepted frame
// is discarded and counted with one discard_o strobe.
`default_nettype none

module frame_decoder (
  input  logic        clk_i,
  input  logic        rst_ni,        // synchronous, active low
  input  logic [7:0]  byte_i,
  input  logic        byte_valid_i,
  output logic [7:0]  seq_o,         // valid with frame_valid_o
  output logic [7:0]  channel_o,     // valid with frame_valid_o (any value: the top checks it)
  output logic [15:0] sample_o,      // valid with frame_valid_o
  output logic        frame_valid_o, // one cycle per accepted frame
  output logic        command_o,     // with frame_valid_o: a command frame (sample_o: the command)
  output logic        discard_o      // one cycle per discarded byte
);

  localparam logic [7:0] SYNC     = 8'hA5;
  localparam logic [7:0] CMD_SYNC = 8'h5A;
  localparam int FrameBytes = 6;

  // window_q[47:40] is the oldest byte, window_q[7:0] the newest.
  logic [8*FrameBytes-1:0] window_q, window_d;
  logic [2:0]              fill_q, fill_d;     // bytes in the window that may still be used
  logic                    fresh_q, fresh_d;   // a byte arrived in the previous cycle
  logic                    discard_q, discard_d;
  logic [7:0]              crc;
  logic                    match;

  crc8 #(.NumBytes(4)) u_crc (
    .data_i(window_q[39:8]),
    .crc_o (crc)
  );

  assign match = fresh_q && fill_q == 3'(FrameBytes) &&
                 (window_q[47:40] == SYNC || window_q[47:40] == CMD_SYNC) && window_q[7:0] == crc;

  always_comb begin
    window_d  = window_q;
    fill_d    = fill_q;
    fresh_d   = 1'b0;
    discard_d = 1'b0;
    if (match) fill_d = '0;
    if (byte_valid_i) begin
      window_d = {window_q[8*FrameBytes-9:0], byte_i};
      fresh_d  = 1'b1;
      // Bytes arrive at least ten bit times apart, so match and byte_valid_i never coincide.
      if (fill_q == 3'(FrameBytes)) discard_d = 1'b1;
      else                          fill_d    = fill_q + 1'b1;
    end
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      window_q  <= '0;
      fill_q    <= '0;
      fresh_q   <= 1'b0;
      discard_q <= 1'b0;
    end else begin
      window_q  <= window_d;
      fill_q    <= fill_d;
      fresh_q   <= fresh_d;
      discard_q <= discard_d;
    end
  end

  assign seq_o         = window_q[39:32];
  assign channel_o     = window_q[31:24];
  assign sample_o      = window_q[23:8];
  assign frame_valid_o = match;
  assign command_o     = window_q[47:40] == CMD_SYNC;
  assign discard_o     = discard_q;

`ifndef SYNTHESIS
  // A byte in the same cycle as an accepted frame would be lost: the UART makes it impossible.
  always @(posedge clk_i) begin
    if (rst_ni && match && byte_valid_i) $error("frame_decoder: byte during a frame match");
  end
`endif

endmodule
