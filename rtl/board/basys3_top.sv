// SPDX-License-Identifier: MIT
// Basys-3 top: the IIR core fed with samples over the USB-UART (framed, checked, resynchronised),
// the filtered clearance on the 7-segment display, flags on the LEDs (docs/board.md).
//
// Link (docs/board.md): host -> board SYNC 0xA5, SEQ, SAMPLE_HI, SAMPLE_LO, CRC-8; board -> host
// SYNC 0xA5, SEQ (echo), OUT_HI, OUT_LO, STATUS, CRC-8. The board handles one frame at a time:
// it is busy from an accepted frame until the last stop bit of its reply. A frame accepted while
// busy is dropped like the core drops an EN while busy (docs/core.md): it never enters the filter,
// gets no reply, and the next reply's STATUS has the overrun bit. A frame that repeats the last
// accepted SEQ is a retransmission: its stored reply is sent again and the filter does not run.
// A command frame (CMD_SYNC 0x5A) with command 0x0001 restarts the session: the core is reset
// (history, flags), the last SEQ forgotten, and the reply has STATUS bit 5 (session reset).
//
// Controls: btnC resets everything; sw[0] = 1 bypasses the filter (the reply is the input sample,
// the filter history is left alone); sw[1] = 1 shows the link-error count (hex) instead of the
// clearance. LEDs: led[0] heartbeat, led[1] overrun, led[2] saturation, led[3] link error (all
// three sticky since reset), led[4] bypass.
`default_nettype none

module basys3_top #(
  parameter RomFile          = "coeffs.mem",  // the coefficient set's coeffs.mem
  parameter int ClksPerBit   = 868,           // 100 MHz / 115200 baud
  parameter int RefreshBits  = 18,            // display: 655 us per digit
  parameter int DebounceBits = 20,            // button: 10.5 ms stable
  parameter int HeartbeatBit = 25             // led[0] toggles every 2^25 cycles (0.34 s)
) (
  input  logic        clk_i,      // W5, 100 MHz
  input  logic        btn_c_i,    // U18, centre button: reset
  input  logic        uart_rx_i,  // B18, RsRx: into the FPGA
  output logic        uart_tx_o,  // A18, RsTx: out of the FPGA
  input  logic [15:0] sw_i,
  output logic [15:0] led_o,
  output logic [6:0]  seg_no,     // CA..CG, active low
  output logic        dp_no,
  output logic [3:0]  an_no
);

  localparam int SampleWidth = iir_coeffs_pkg::SampleWidth;
  if (SampleWidth != 16) begin : g_bad_width
    $error("basys3_top: the link carries 16-bit samples");
  end

  // STATUS byte bits (docs/board.md).
  localparam int StOverrun    = 0;
  localparam int StSaturation = 1;
  localparam int StLinkError  = 2;
  localparam int StBypass     = 3;
  localparam int StRetransmit = 4;
  localparam int StSessionReset = 5;
  localparam logic [15:0] CMD_RESET = 16'h0001;

  // Reset: a power-on count (registers start at 0 in the FPGA), then the debounced button //
  logic [3:0] por_q, por_d;
  logic       btn;
  logic       rst_n;

  assign por_d = &por_q ? por_q : por_q + 1'b1;
  always_ff @(posedge clk_i) por_q <= por_d;

  button_debounce #(.StableBits(DebounceBits)) u_btn (
    .clk_i,
    .btn_i(btn_c_i),
    .btn_o(btn)
  );
  assign rst_n = &por_q && !btn;

  // Switches: synchronised (they are asynchronous and slow; no debouncing needed).
  logic [1:0] sw_meta_q, sw_q;
  always_ff @(posedge clk_i) begin
    sw_meta_q <= sw_i[1:0];
    sw_q      <= sw_meta_q;
  end
  logic bypass, show_errors;
  assign bypass      = sw_q[0];
  assign show_errors = sw_q[1];

  // UART and framing //
  logic [7:0]  rx_byte;
  logic        rx_valid, rx_frame_err;
  logic [7:0]  frame_seq;
  logic [15:0] frame_sample;
  logic        frame_valid, frame_command, frame_discard;
  logic [7:0]  tx_byte;
  logic        tx_valid, tx_ready;

  uart_rx #(.ClksPerBit(ClksPerBit)) u_uart_rx (
    .clk_i,
    .rst_ni      (rst_n),
    .rx_i        (uart_rx_i),
    .data_o      (rx_byte),
    .data_valid_o(rx_valid),
    .frame_err_o (rx_frame_err)
  );

  frame_decoder u_decoder (
    .clk_i,
    .rst_ni       (rst_n),
    .byte_i       (rx_byte),
    .byte_valid_i (rx_valid),
    .seq_o        (frame_seq),
    .sample_o     (frame_sample),
    .frame_valid_o(frame_valid),
    .command_o    (frame_command),
    .discard_o    (frame_discard)
  );

  // The filter //
  logic signed [15:0] core_out;
  logic               core_valid, core_busy, core_overrun, core_saturation;
  logic               core_strobe, core_clear, core_reset;
  logic               core_rst_n_q;

  // The core's reset from a flip-flop: a reset decoded from a frame straight into the core's
  // synchronous resets costs about 250 LUTs (Yosys cannot use the plain FDRE reset pin then).
  always_ff @(posedge clk_i) core_rst_n_q <= rst_n && !core_reset;

  // The board serves channel 0 of the core: its frames carry no channel number yet.
  /* verilator lint_off UNUSEDSIGNAL */
  logic [iir_coeffs_pkg::ChannelWidth-1:0] core_channel;
  logic                                    core_channel_error;
  /* verilator lint_on UNUSEDSIGNAL */

  iir_core #(.RomFile(RomFile)) u_core (
    .clk_i,
    .rst_ni         (core_rst_n_q),
    .sample_i       (frame_sample),
    .channel_i      ('0),
    .sample_valid_i (core_strobe),
    .sample_o       (core_out),
    .channel_o      (core_channel),
    .sample_valid_o (core_valid),
    .busy_o         (core_busy),
    .overrun_o      (core_overrun),
    .saturation_o   (core_saturation),
    .channel_error_o(core_channel_error),
    .flag_clear_i   (core_clear)
  );

  // Control: one frame at a time //
  typedef enum logic [1:0] {StIdle, StCore, StReply, StWait} state_e;

  state_e      state_q, state_d;
  logic [7:0]  seq_q, seq_d;          // the SEQ being answered (and the last accepted one)
  logic        have_seq_q, have_seq_d;
  logic [15:0] out_q, out_d;          // OUT of the reply being formed or sent
  logic [7:0]  status_q, status_d;
  logic        bypass_q, bypass_d;    // the frame being answered was bypassed
  logic        overrun_q, overrun_d;  // pending: reported in the next reply
  logic        link_err_q, link_err_d;
  logic [2:0]  sticky_q, sticky_d;    // LEDs: overrun, saturation, link error since reset
  logic [15:0] err_count_q, err_count_d;
  logic        send, send_q, retransmit_q, retransmit_d;
  logic        session_reset_q, session_reset_d;  // the reply being formed answers a reset
  logic        enc_busy;
  logic        overrun_event, link_err_event;

  assign overrun_event  = frame_valid && state_q != StIdle;
  assign link_err_event = frame_discard || rx_frame_err;

  always_comb begin
    state_d      = state_q;
    seq_d        = seq_q;
    have_seq_d   = have_seq_q;
    out_d        = out_q;
    status_d     = status_q;
    bypass_d     = bypass_q;
    retransmit_d = retransmit_q;
    session_reset_d = session_reset_q;
    overrun_d    = overrun_q || overrun_event;
    link_err_d   = link_err_q || link_err_event;
    sticky_d     = sticky_q;
    err_count_d  = err_count_q + {15'd0, link_err_event && err_count_q != 16'hffff};
    core_strobe  = 1'b0;
    core_clear   = 1'b0;
    core_reset   = 1'b0;
    send         = 1'b0;
    unique case (state_q)
      StIdle: begin
        if (frame_valid && frame_command) begin
          // Unknown commands are ignored (no reply): only a reset is defined.
          if (frame_sample == CMD_RESET) begin
            core_reset      = 1'b1;  // the core is idle with zero history from the next cycle
            seq_d           = frame_seq;
            have_seq_d      = 1'b0;  // the next sample frame is new whatever its SEQ
            out_d           = '0;
            bypass_d        = 1'b0;
            retransmit_d    = 1'b0;
            session_reset_d = 1'b1;
            state_d         = StReply;
          end
        end else if (frame_valid) begin
          session_reset_d = 1'b0;
          if (have_seq_q && frame_seq == seq_q) begin
            retransmit_d = 1'b1;  // the reply of this SEQ went missing: send it again
            state_d      = StReply;
          end else begin
            seq_d        = frame_seq;
            have_seq_d   = 1'b1;
            bypass_d     = bypass;
            retransmit_d = 1'b0;
            if (bypass) begin
              out_d   = frame_sample;
              state_d = StReply;
            end else begin
              core_strobe = 1'b1;
              state_d     = StCore;
            end
          end
        end
      end
      StCore: begin
        if (core_valid) begin
          out_d   = core_out;
          state_d = StReply;
        end
      end
      StReply: begin
        send    = 1'b1;
        state_d = StWait;
        if (retransmit_q) begin
          status_d = status_q | 8'(1 << StRetransmit);  // pending flags wait for a new reply
        end else begin
          status_d = '0;
          status_d[StOverrun]    = overrun_q || overrun_event || core_overrun;
          status_d[StSaturation] = core_saturation;
          status_d[StLinkError]  = link_err_q || link_err_event;
          status_d[StBypass]     = bypass_q;
          status_d[StSessionReset] = session_reset_q;
          overrun_d              = 1'b0;
          link_err_d             = 1'b0;
          core_clear             = 1'b1;  // a core flag event at this edge survives the clear
          sticky_d               = sticky_q | status_d[2:0];
        end
      end
      StWait: begin
        if (!enc_busy && !send_q) state_d = StIdle;
      end
      default: state_d = StIdle;
    endcase
  end

  always_ff @(posedge clk_i) begin
    if (!rst_n) begin
      state_q      <= StIdle;
      seq_q        <= '0;
      have_seq_q   <= 1'b0;
      out_q        <= '0;
      status_q     <= '0;
      bypass_q     <= 1'b0;
      retransmit_q <= 1'b0;
      session_reset_q <= 1'b0;
      overrun_q    <= 1'b0;
      link_err_q   <= 1'b0;
      sticky_q     <= '0;
      err_count_q  <= '0;
    end else begin
      state_q      <= state_d;
      seq_q        <= seq_d;
      have_seq_q   <= have_seq_d;
      out_q        <= out_d;
      status_q     <= status_d;
      bypass_q     <= bypass_d;
      retransmit_q <= retransmit_d;
      session_reset_q <= session_reset_d;
      overrun_q    <= overrun_d;
      link_err_q   <= link_err_d;
      sticky_q     <= sticky_d;
      err_count_q  <= err_count_d;
    end
  end

  // The encoder latches SEQ, OUT and STATUS in the cycle after StReply (send is registered).
  always_ff @(posedge clk_i) begin
    if (!rst_n) send_q <= 1'b0;
    else        send_q <= send;
  end

  frame_encoder u_encoder (
    .clk_i,
    .rst_ni    (rst_n),
    .seq_i     (seq_q),
    .sample_i  (out_q),
    .status_i  (status_q),
    .send_i    (send_q),
    .busy_o    (enc_busy),
    .tx_data_o (tx_byte),
    .tx_valid_o(tx_valid),
    .tx_ready_i(tx_ready)
  );

  uart_tx #(.ClksPerBit(ClksPerBit)) u_uart_tx (
    .clk_i,
    .rst_ni      (rst_n),
    .data_i      (tx_byte),
    .data_valid_i(tx_valid),
    .ready_o     (tx_ready),
    .tx_o        (uart_tx_o)
  );

  // Display and LEDs //
  logic [19:0] clearance_digits, digits;
  logic [3:0]  clearance_dp, dp;
  logic [HeartbeatBit:0] beat_q, beat_d;

  clearance_display u_clearance (
    .clk_i,
    .rst_ni  (rst_n),
    .word_i  (out_q),
    .digits_o(clearance_digits),
    .dp_o    (clearance_dp)
  );
  assign digits = show_errors ? {1'b0, err_count_q[15:12], 1'b0, err_count_q[11:8],
                                 1'b0, err_count_q[7:4], 1'b0, err_count_q[3:0]}
                              : clearance_digits;
  assign dp     = show_errors ? 4'b0000 : clearance_dp;

  seven_seg #(.RefreshBits(RefreshBits)) u_display (
    .clk_i,
    .rst_ni  (rst_n),
    .digits_i(digits),
    .dp_i    (dp),
    .seg_no,
    .dp_no,
    .an_no
  );

  assign beat_d = beat_q + 1'b1;
  always_ff @(posedge clk_i) begin
    if (!rst_n) beat_q <= '0;
    else        beat_q <= beat_d;
  end

  assign led_o = {11'd0, bypass, sticky_q, beat_q[HeartbeatBit]};

  // sw[15:2] are unused; core_busy only feeds the assertion.
  logic unused_sw;
  assign unused_sw = ^{sw_i[15:2], core_busy};

`ifndef SYNTHESIS
  // The control FSM strobes the core only in StIdle, after the previous output: never while busy.
  always @(posedge clk_i) begin
    if (rst_n && core_strobe && core_busy) $error("basys3_top: core strobed while busy");
  end
`endif

endmodule
