// SPDX-License-Identifier: MIT
// Basys-3 top: the IIR core fed with samples over the USB-UART (framed, checked, resynchronised),
// the filtered clearance on the 7-segment display, flags on the LEDs (docs/board.md).
//
// Link (docs/board.md): host -> board SYNC 0xA5, SEQ, CHANNEL, SAMPLE_HI, SAMPLE_LO, CRC-8;
// board -> host SYNC 0xA5, SEQ (echo), CHANNEL (echo), OUT_HI, OUT_LO, STATUS, CRC-8. Accepted
// frames wait in a queue of QueueDepth and are answered one after another, so a host may keep
// that many requests in flight; a frame that finds the queue full is dropped like the core drops
// an EN while busy (docs/core.md): it never enters the filter, gets no reply, and the next reply
// on its channel has the overrun bit. Every sample reply is kept under its SEQ: a frame that
// repeats an answered one (the last SEQ and CHANNEL; in a windowed session any of the last
// QueueDepth) is a retransmission, answered with the stored reply without filtering again. A
// windowed session takes new frames only in SEQ order (a frame after a lost one is dropped
// unanswered until the lost one comes again). A frame whose CHANNEL the core does not have is
// answered with OUT = 0 and the channel-error bit and never enters the filter. OVERRUN and
// SATURATION in a reply are those of its channel. A command frame (CMD_SYNC 0x5A) with command
// 0x0001 (0x0002: windowed) restarts the session: the core is reset (every channel's history and
// flags), the stored replies forgotten, and the reply has STATUS bit 5 (session reset) and OUT =
// the number of channels.
//
// Controls: btnC resets everything; sw[0] = 1 bypasses the filter (the reply is the input sample,
// the filter history is left alone); sw[1] = 1 shows the link-error count (hex) instead of the
// clearance; sw[15:12] choose the channel the display shows. LEDs: led[0] heartbeat, led[1]
// overrun, led[2] saturation, led[3] link error, led[4] bypass, led[5] channel error (led[1-3]
// and led[5] sticky since reset).
`default_nettype none

module basys3_top #(
  parameter RomFile          = "coeffs.mem",  // the coefficient set's coeffs.mem
  // 100 MHz / baud, >= 4: 868 for 115200 baud, 109 for 921600 (docs/board.md, "Link budget").
  parameter int ClksPerBit   = 868,
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

  localparam int SampleWidth  = iir_coeffs_pkg::SampleWidth;
  localparam int NumChannels  = iir_coeffs_pkg::NumChannels;
  localparam int ChannelWidth = iir_coeffs_pkg::ChannelWidth;
  if (SampleWidth != 16) begin : g_bad_width
    $error("basys3_top: the link carries 16-bit samples");
  end
  if (NumChannels > 255) begin : g_bad_channels
    $error("basys3_top: the session-reset reply reports the channel count in one byte (<= 255)");
  end

  // STATUS byte bits (docs/board.md).
  localparam int StOverrun    = 0;
  localparam int StSaturation = 1;
  localparam int StLinkError  = 2;
  localparam int StBypass     = 3;
  localparam int StRetransmit = 4;
  localparam int StSessionReset = 5;
  localparam int StChannelError = 6;
  localparam int StWindowed     = 7;
  localparam logic [15:0] CMD_RESET          = 16'h0001;
  localparam logic [15:0] CMD_RESET_WINDOWED = 16'h0002;
  // Frames in flight: the queue's depth, the reply store's and a windowed host's largest window.
  localparam int QueueDepth    = 32;
  localparam int QueueAddrBits = $clog2(QueueDepth);

  // Reset: a power-on count (registers start at 0 in the FPGA), then the debounced button //
  logic [3:0] por_q, por_d;
  logic       btn;
  logic       rst_n, rst_n_q, rst_n_d;

  assign por_d = &por_q ? por_q : por_q + 1'b1;
  always_ff @(posedge clk_i) por_q <= por_d;

  button_debounce #(.StableBits(DebounceBits)) u_btn (
    .clk_i,
    .btn_i(btn_c_i),
    .btn_o(btn)
  );
  // Registered: the reset drives some 390 register inputs, a net the estimate allows 4.4 ns of the
  // 10 ns cycle on its own (docs/synthesis.md, "Timing estimate"). Registers start at 0: in reset.
  assign rst_n_d = &por_q && !btn;
  always_ff @(posedge clk_i) rst_n_q <= rst_n_d;
  assign rst_n = rst_n_q;
  // Two more copies, a cycle later, for the link's and the display's modules, so that no copy
  // drives much more than 250 resets (one copy: a net of some 500 loads after its inverter, 5.5 ns
  // of allowance). A copy of rst_n_d itself would be merged back into rst_n_q by synthesis. The
  // link's modules leave reset a cycle after the rest, long before a byte can arrive.
  logic rst_n_link_q, rst_n_view_q;
  always_ff @(posedge clk_i) rst_n_link_q <= rst_n_q;
  always_ff @(posedge clk_i) rst_n_view_q <= rst_n_q;

  // Switches: synchronised (they are asynchronous and slow; no debouncing needed).
  logic [5:0] sw_meta_q, sw_q;
  always_ff @(posedge clk_i) begin
    sw_meta_q <= {sw_i[15:12], sw_i[1:0]};
    sw_q      <= sw_meta_q;
  end
  logic       bypass, show_errors;
  logic [3:0] display_chan;
  assign bypass       = sw_q[0];
  assign show_errors  = sw_q[1];
  assign display_chan = sw_q[5:2];

  // UART and framing //
  logic [7:0]  rx_byte;
  logic        rx_valid, rx_frame_err;
  logic [7:0]  dec_seq, dec_channel;
  logic [15:0] dec_sample;
  logic        dec_valid, dec_command, frame_discard;
  logic [7:0]  frame_seq, frame_channel;
  logic [15:0] frame_sample;
  logic        frame_valid, frame_command;
  logic [7:0]  tx_byte;
  logic        tx_valid, tx_ready;

  uart_rx #(.ClksPerBit(ClksPerBit)) u_uart_rx (
    .clk_i,
    .rst_ni      (rst_n_link_q),
    .rx_i        (uart_rx_i),
    .data_o      (rx_byte),
    .data_valid_o(rx_valid),
    .frame_err_o (rx_frame_err)
  );

  frame_decoder u_decoder (
    .clk_i,
    .rst_ni       (rst_n_link_q),
    .byte_i       (rx_byte),
    .byte_valid_i (rx_valid),
    .seq_o        (dec_seq),
    .channel_o    (dec_channel),
    .sample_o     (dec_sample),
    .frame_valid_o(dec_valid),
    .command_o    (dec_command),
    .discard_o    (frame_discard)
  );

  // The decoded frame, registered: its CRC check and the queue's push would otherwise be one path
  // of ten LUT levels (docs/synthesis.md, "Timing estimate"). A frame waits one cycle more.
  logic            frame_valid_q, frame_valid_d;
  logic [8+8+16:0] frame_fields_q, frame_fields_d;  // command, SEQ, CHANNEL, SAMPLE
  assign frame_valid_d  = dec_valid;
  assign frame_fields_d = {dec_command, dec_seq, dec_channel, dec_sample};
  always_ff @(posedge clk_i) begin
    if (!rst_n) frame_valid_q <= 1'b0;
    else        frame_valid_q <= frame_valid_d;
  end
  always_ff @(posedge clk_i) frame_fields_q <= frame_fields_d;
  assign frame_valid = frame_valid_q;
  assign {frame_command, frame_seq, frame_channel, frame_sample} = frame_fields_q;

  // The filter //
  logic signed [15:0]      core_out;
  logic                    core_valid, core_busy, core_channel_error;
  logic [ChannelWidth-1:0] core_channel;
  logic [NumChannels-1:0]  core_overrun, core_saturation;
  logic                    core_strobe, core_clear, core_reset;
  logic                    core_rst_n_q;
  logic [ChannelWidth-1:0] core_channel_in;
  logic signed [15:0]      core_sample_in;

  // The core's reset from a flip-flop: a reset decoded from a frame straight into the core's
  // synchronous resets costs about 250 LUTs (Yosys cannot use the plain FDRE reset pin then).
  always_ff @(posedge clk_i) core_rst_n_q <= rst_n && !core_reset;

  iir_core #(.RomFile(RomFile)) u_core (
    .clk_i,
    .rst_ni         (core_rst_n_q),
    .sample_i       (core_sample_in),
    .channel_i      (core_channel_in),
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

  // The channel a CHANNEL byte names, one-hot (none for a channel the core lacks).
  function automatic logic [NumChannels-1:0] channel_bit(logic [7:0] chan);
    channel_bit = '0;
    for (int c = 0; c < NumChannels; c++) channel_bit[c] = (32'(chan) == c);
  endfunction

  // The frame queue //
  // Accepted frames wait here in arrival order while the board answers earlier ones (a reply,
  // seven bytes, is longer than a request): a host may keep up to QueueDepth requests in flight.
  // A sample frame that finds the queue full is dropped; the next frame of its channel to enter
  // the queue carries the mark, so that its reply has OVERRUN (a retransmission passes the mark
  // on to the channel's next new reply).
  typedef struct packed {
    logic        command;
    logic        dropped_before;  // a frame of this channel was dropped since the previous one
    logic [7:0]  seq;
    logic [7:0]  channel;
    logic [15:0] sample;
  } frame_t;

  // Plain words: Yosys 0.23 does not take an unpacked array of a struct type as a memory.
  localparam int FrameBits = 2 + 8 + 8 + 16;  // frame_t's width
  logic [FrameBits-1:0]   queue_mem [QueueDepth];
  logic [QueueAddrBits:0] q_wr_q, q_wr_d, q_rd_q, q_rd_d;  // one extra bit tells full from empty
  logic                   q_empty, q_full, q_push, q_pop;
  frame_t                 head;
  logic [FrameBits-1:0]   q_entry, head_read_q, head_read_d;
  logic [QueueAddrBits:0] q_wr_seen_q, q_wr_seen_d;  // q_wr_q a cycle late: the frames head shows
  logic [NumChannels-1:0] push_bit;                   // the channel of a sample frame pushed
  logic [NumChannels-1:0] drop_pend_q, drop_pend_d;  // a dropped frame's mark, waiting for a push

  assign q_wr_seen_d = q_wr_q;
  assign q_empty = q_wr_seen_q == q_rd_q;
  assign q_full  = q_wr_q == {~q_rd_q[QueueAddrBits], q_rd_q[QueueAddrBits-1:0]};
  assign q_push  = frame_valid && !q_full;
  assign push_bit = frame_command ? '0 : channel_bit(frame_channel);
  assign q_wr_d  = q_wr_q + {QueueAddrBits'(0), q_push};
  assign q_rd_d  = q_rd_q + {QueueAddrBits'(0), q_pop};
  assign q_entry = {frame_command, |(drop_pend_q & push_bit), frame_seq, frame_channel,
                    frame_sample};

  always_ff @(posedge clk_i) begin
    if (q_push) queue_mem[q_wr_q[QueueAddrBits-1:0]] <= q_entry;
  end
  // The head frame is read a cycle ahead, at the next read pointer, into a register, so that the
  // decisions on it start at a register and not after a memory read (docs/synthesis.md, "Timing
  // estimate"); the read is not transparent, so synthesis keeps the register after the memory.
  // A frame written at one edge is in that register from the next, so the queue counts it from
  // then: q_empty compares q_rd_q with q_wr_q a cycle late, and head is queue_mem[q_rd_q]
  // whenever the queue is not empty.
  assign head_read_d = queue_mem[q_rd_d[QueueAddrBits-1:0]];
  always_ff @(posedge clk_i) head_read_q <= head_read_d;
  assign head = head_read_q;

  // The reply store //
  // Every sample reply is kept under its SEQ's low bits, so that a retransmission of any of the
  // last QueueDepth frames is answered with the reply it had (docs/board.md, "Windowed session").
  typedef struct packed {
    logic [7:0]  channel;
    logic [15:0] out;
    logic [7:0]  status;
  } stored_t;

  localparam int StoredBits = 8 + 16 + 8;  // stored_t's width
  logic [StoredBits-1:0]  store_mem [QueueDepth];
  logic [QueueDepth-1:0]  stored_q, stored_d;  // the entry holds a reply of this session
  logic                   store_we;
  stored_t                stored;              // the entry of the head frame's SEQ

  assign stored = store_mem[head.seq[QueueAddrBits-1:0]];

  // Control: the frames of the queue one after another //
  typedef enum logic [1:0] {StIdle, StCore, StReply, StWait} state_e;

  state_e      state_q, state_d;
  logic [7:0]  seq_q, seq_d;            // the SEQ being answered (and the last answered one)
  logic [7:0]  chan_q, chan_d;          // its CHANNEL
  logic        have_seq_q, have_seq_d;
  logic        window_q, window_d;      // windowed session: SEQs in order (docs/board.md)
  logic [7:0]  expect_q, expect_d;      // windowed: the SEQ of the next new frame
  logic [15:0] out_q, out_d;            // the filtered or bypassed sample being answered
  logic [15:0] retx_out_q, retx_out_d;  // OUT of a retransmitted reply
  logic [7:0]  status_q, status_d;
  logic [7:0]  reply_status;            // STATUS of a new reply
  logic [15:0] reply_out;               // OUT of the reply
  logic        bypass_q, bypass_d;      // the frame being answered was bypassed
  logic        chan_err_q, chan_err_d;  // the frame being answered names no channel of the core
  logic        link_err_q, link_err_d;  // pending: reported in the next reply
  logic [3:0]  sticky_q, sticky_d;      // LEDs: overrun, saturation, link and channel error
  logic [15:0] err_count_q, err_count_d;
  logic        send, send_q, retransmit_q, retransmit_d;
  logic        session_reset_q, session_reset_d;  // the reply being formed answers a reset
  logic        enc_busy;
  logic        head_channel_ok;         // the head frame's CHANNEL is one of the core's
  logic [7:0]  head_age;                // windowed: how many SEQs ago the head frame was new
  logic        head_repeat;             // the head frame is a retransmission
  logic        cur_dropped_q, cur_dropped_d;  // the frame being answered carries a drop mark
  logic        session_start;           // a session-reset command leaves the queue

  // The head frame's classification, registered (head_*_q): from the head register through the
  // SEQ's age, the stored reply's CHANNEL and the compares to the core's strobe is a path of about
  // ten LUT levels, which the twelve-channel top would not close at 100 MHz (docs/synthesis.md,
  // "Timing estimate"). The classes are taken only once they are settled (head_settled_q): the
  // head was the head in the cycle before and nothing they read changed then (a pop or a reply
  // being stored). A frame reaching an empty queue therefore waits one cycle more.
  logic head_channel_ok_d, head_repeat_d, head_in_order_d, head_reset_d;
  logic head_channel_ok_q, head_repeat_q, head_in_order_q, head_reset_q;
  logic head_settled_q, head_settled_d;
  logic head_ready;  // a head frame whose classes are settled

  // All eight bits count: channel 16 must not reach channel 0 through a 4-bit channel_i.
  assign head_channel_ok_d = 32'(head.channel) < NumChannels;
  // A retransmission repeats an answered frame: in a windowed session one of the last QueueDepth
  // SEQs with the CHANNEL it had, otherwise the last answered SEQ and CHANNEL.
  assign head_age      = expect_q - head.seq;
  assign head_repeat_d = window_q
      ? head_age != 8'd0 && 32'(head_age) <= QueueDepth &&
        stored_q[head.seq[QueueAddrBits-1:0]] && stored.channel == head.channel
      : have_seq_q && head.seq == seq_q && head.channel == chan_q;
  // A new frame is taken in SEQ order in a windowed session, in any order otherwise.
  assign head_in_order_d = !window_q || head.seq == expect_q;
  // Only the two resets are defined commands; any other is ignored (no reply).
  assign head_reset_d    = head.sample == CMD_RESET || head.sample == CMD_RESET_WINDOWED;
  assign head_settled_d  = !q_empty && !q_pop && state_q != StReply;
  assign head_ready      = !q_empty && head_settled_q;
  assign head_channel_ok = head_channel_ok_q;
  assign head_repeat     = head_repeat_q;

  always_ff @(posedge clk_i) begin
    head_channel_ok_q <= head_channel_ok_d;
    head_repeat_q     <= head_repeat_d;
    head_in_order_q   <= head_in_order_d;
    head_reset_q      <= head_reset_d;
  end
  always_ff @(posedge clk_i) begin
    if (!rst_n) head_settled_q <= 1'b0;
    else        head_settled_q <= head_settled_d;
  end

  // The core is strobed only for a channel it has: with one channel that is 0, and a constant
  // channel_i lets synthesis drop the core's channel logic (measurement_sos: 47 LUT6 sites, 18
  // CARRY4).
  assign core_channel_in = NumChannels == 1 ? '0 : head.channel[ChannelWidth-1:0];
  assign core_sample_in  = head.sample;

  // The display's values: each channel's latest filtered or bypassed sample //
  logic [NumChannels*16-1:0] shown_q, shown_d;

  function automatic logic [NumChannels*16-1:0] show_on(logic [NumChannels*16-1:0] shown,
                                                         logic [7:0] chan, logic [15:0] word);
    show_on = shown;
    for (int c = 0; c < NumChannels; c++) if (32'(chan) == c) show_on[16*c +: 16] = word;
  endfunction

  // Per-channel flags //
  // The core's sticky flags move into the board's pending bits as soon as they rise (and are
  // cleared in the core), so that a reply can clear its own channel's bits and keep the others.
  // A sample frame dropped because the queue is full marks the channel its CHANNEL byte names (a
  // dropped command marks none: its CHANNEL is only echoed).

  logic                   overrun_event, link_err_event;
  logic [NumChannels-1:0] ovr_now, sat_now, reply_bit;
  logic [NumChannels-1:0] pend_ovr_q, pend_ovr_d, pend_sat_q, pend_sat_d;

  assign overrun_event  = frame_valid && q_full;
  assign link_err_event = frame_discard || rx_frame_err;
  assign drop_pend_d    = session_start ? '0 :
                          overrun_event ? drop_pend_q | push_bit :
                          q_push        ? drop_pend_q & ~push_bit : drop_pend_q;
  assign ovr_now        = pend_ovr_q | core_overrun;
  assign sat_now        = pend_sat_q | core_saturation;
  assign reply_bit      = channel_bit(chan_q);
  assign core_clear     = |{core_overrun, core_saturation};

  // A new reply's STATUS: its channel's flags (every channel's for a session reset, which clears
  // them all), the link errors since the previous reply, and what this reply is.
  always_comb begin
    reply_status                 = '0;
    reply_status[StOverrun]      = session_reset_q ? |{ovr_now, drop_pend_q}
                                                   : |(ovr_now & reply_bit) || cur_dropped_q;
    reply_status[StSaturation]   = session_reset_q ? |sat_now : |(sat_now & reply_bit);
    reply_status[StLinkError]    = link_err_q || link_err_event;
    reply_status[StBypass]       = bypass_q;
    reply_status[StSessionReset] = session_reset_q;
    reply_status[StChannelError] = chan_err_q;
    reply_status[StWindowed]     = window_q;
  end
  assign reply_out = retransmit_q ? retx_out_q :
                     session_reset_q ? 16'(NumChannels) : chan_err_q ? '0 : out_q;
  assign store_we  = state_q == StReply && !retransmit_q && !session_reset_q;
  always_ff @(posedge clk_i) begin
    if (store_we) store_mem[seq_q[QueueAddrBits-1:0]] <= {chan_q, reply_out, reply_status};
  end
  // The LEDs light at the event: a channel that is never answered again still shows its overrun.
  assign sticky_d    = sticky_q | {state_q == StReply && chan_err_q, link_err_event,
                                   |core_saturation, overrun_event || |core_overrun};
  assign err_count_d = err_count_q + {15'd0, link_err_event && err_count_q != 16'hffff};

  // Takes the head frame off the queue: a command, a retransmission, a new sample or (windowed,
  // SEQ out of order: an earlier frame was lost) nothing.
  always_comb begin
    state_d         = state_q;
    seq_d           = seq_q;
    chan_d          = chan_q;
    have_seq_d      = have_seq_q;
    window_d        = window_q;
    expect_d        = expect_q;
    out_d           = out_q;
    retx_out_d      = retx_out_q;
    status_d        = status_q;
    bypass_d        = bypass_q;
    chan_err_d      = chan_err_q;
    retransmit_d    = retransmit_q;
    session_reset_d = session_reset_q;
    stored_d        = stored_q | (store_we ? QueueDepth'(1) << seq_q[QueueAddrBits-1:0] : '0);
    pend_ovr_d      = ovr_now;
    cur_dropped_d   = cur_dropped_q;
    session_start   = 1'b0;
    pend_sat_d      = sat_now;
    link_err_d      = link_err_q || link_err_event;
    shown_d         = shown_q;
    q_pop           = 1'b0;
    core_strobe     = 1'b0;
    core_reset      = 1'b0;
    send            = 1'b0;
    unique case (state_q)
      StIdle: begin
        if (head_ready) begin
          q_pop = 1'b1;
          // Only a new sample's reply reports the mark; otherwise it waits for the next one.
          if (head.dropped_before) pend_ovr_d = ovr_now | channel_bit(head.channel);
          if (head.command) begin
            // Unknown commands are ignored (no reply): only the two resets are defined.
            if (head_reset_q) begin
              core_reset      = 1'b1;  // the core is idle with zero history from the next cycle
              session_start   = 1'b1;
              seq_d           = head.seq;
              chan_d          = head.channel;
              have_seq_d      = 1'b0;  // the next sample frame is new whatever its SEQ
              window_d        = head.sample == CMD_RESET_WINDOWED;
              expect_d        = head.seq + 8'd1;
              stored_d        = '0;
              shown_d         = '0;
              out_d           = '0;
              bypass_d        = 1'b0;
              chan_err_d      = 1'b0;
              retransmit_d    = 1'b0;
              session_reset_d = 1'b1;
              state_d         = StReply;
            end
          end else if (head_repeat) begin
            // The reply of this frame went missing: send it again, do not filter again.
            seq_d           = head.seq;
            chan_d          = head.channel;
            retx_out_d      = stored.out;
            status_d        = stored.status | 8'(1 << StRetransmit);
            retransmit_d    = 1'b1;
            session_reset_d = 1'b0;
            state_d         = StReply;
          end else if (head_in_order_q) begin
            seq_d           = head.seq;
            chan_d          = head.channel;
            have_seq_d      = 1'b1;
            pend_ovr_d      = ovr_now;
            cur_dropped_d   = head.dropped_before;
            expect_d        = head.seq + 8'd1;
            bypass_d        = head_channel_ok && bypass;
            chan_err_d      = !head_channel_ok;
            retransmit_d    = 1'b0;
            session_reset_d = 1'b0;
            if (!head_channel_ok) begin
              state_d = StReply;  // answered with the channel-error bit, never filtered
            end else if (bypass) begin
              out_d   = head.sample;
              shown_d = show_on(shown_q, head.channel, head.sample);
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
          shown_d = show_on(shown_q, chan_q, core_out);
          state_d = StReply;
        end
      end
      StReply: begin
        send    = 1'b1;
        state_d = StWait;
        if (!retransmit_q) begin  // a retransmission leaves the pending flags for a new reply
          status_d   = reply_status;
          link_err_d = 1'b0;
          pend_ovr_d = session_reset_q ? '0 : ovr_now & ~reply_bit;
          pend_sat_d = session_reset_q ? '0 : sat_now & ~reply_bit;
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
      state_q         <= StIdle;
      q_wr_q          <= '0;
      q_wr_seen_q     <= '0;
      q_rd_q          <= '0;
      seq_q           <= '0;
      chan_q          <= '0;
      have_seq_q      <= 1'b0;
      window_q        <= 1'b0;
      expect_q        <= '0;
      out_q           <= '0;
      retx_out_q      <= '0;
      status_q        <= '0;
      bypass_q        <= 1'b0;
      chan_err_q      <= 1'b0;
      retransmit_q    <= 1'b0;
      session_reset_q <= 1'b0;
      stored_q        <= '0;
      shown_q         <= '0;
      pend_ovr_q      <= '0;
      pend_sat_q      <= '0;
      link_err_q      <= 1'b0;
      drop_pend_q     <= '0;
      cur_dropped_q   <= 1'b0;
      sticky_q        <= '0;
      err_count_q     <= '0;
    end else begin
      state_q         <= state_d;
      q_wr_q          <= q_wr_d;
      q_wr_seen_q     <= q_wr_seen_d;
      q_rd_q          <= q_rd_d;
      seq_q           <= seq_d;
      chan_q          <= chan_d;
      have_seq_q      <= have_seq_d;
      window_q        <= window_d;
      expect_q        <= expect_d;
      out_q           <= out_d;
      retx_out_q      <= retx_out_d;
      status_q        <= status_d;
      bypass_q        <= bypass_d;
      chan_err_q      <= chan_err_d;
      retransmit_q    <= retransmit_d;
      session_reset_q <= session_reset_d;
      stored_q        <= stored_d;
      shown_q         <= shown_d;
      pend_ovr_q      <= pend_ovr_d;
      pend_sat_q      <= pend_sat_d;
      link_err_q      <= link_err_d;
      drop_pend_q     <= drop_pend_d;
      cur_dropped_q   <= cur_dropped_d;
      sticky_q        <= sticky_d;
      err_count_q     <= err_count_d;
    end
  end

  // The encoder latches SEQ, CHANNEL, OUT and STATUS in the cycle after StReply (send is
  // registered).
  always_ff @(posedge clk_i) begin
    if (!rst_n) send_q <= 1'b0;
    else        send_q <= send;
  end

  frame_encoder u_encoder (
    .clk_i,
    .rst_ni    (rst_n_link_q),
    .seq_i     (seq_q),
    .channel_i (chan_q),
    .sample_i  (reply_out),
    .status_i  (status_q),
    .send_i    (send_q),
    .busy_o    (enc_busy),
    .tx_data_o (tx_byte),
    .tx_valid_o(tx_valid),
    .tx_ready_i(tx_ready)
  );

  uart_tx #(.ClksPerBit(ClksPerBit)) u_uart_tx (
    .clk_i,
    .rst_ni      (rst_n_link_q),
    .data_i      (tx_byte),
    .data_valid_i(tx_valid),
    .ready_o     (tx_ready),
    .tx_o        (uart_tx_o)
  );

  // Display and LEDs //
  logic [19:0] clearance_digits, digits;
  logic [3:0]  clearance_dp, dp;
  logic [HeartbeatBit:0] beat_q, beat_d;
  // The latest sample of the channel sw[15:12] choose, and that sample registered.
  logic [15:0]           shown_word, shown_word_q;
  logic                  shown_ok;    // the core has that channel
  localparam logic [19:0] DASHES = {4{5'd17}};

  // Registered before the conversion: the channel select and the conversion's adders would be one
  // path of about thirteen LUT levels with twelve channels (docs/synthesis.md, "Timing estimate").
  always_comb begin
    shown_word = '0;
    for (int c = 0; c < NumChannels; c++) if (32'(display_chan) == c) shown_word = shown_q[16*c +: 16];
  end
  always_ff @(posedge clk_i) shown_word_q <= shown_word;
  assign shown_ok = 32'(display_chan) < NumChannels;

  clearance_display u_clearance (
    .clk_i,
    .rst_ni  (rst_n_view_q),
    .word_i  (shown_word_q),
    .digits_o(clearance_digits),
    .dp_o    (clearance_dp)
  );
  assign digits = show_errors ? {1'b0, err_count_q[15:12], 1'b0, err_count_q[11:8],
                                 1'b0, err_count_q[7:4], 1'b0, err_count_q[3:0]}
                : shown_ok    ? clearance_digits : DASHES;
  assign dp     = show_errors || !shown_ok ? 4'b0000 : clearance_dp;

  seven_seg #(.RefreshBits(RefreshBits)) u_display (
    .clk_i,
    .rst_ni  (rst_n_view_q),
    .digits_i(digits),
    .dp_i    (dp),
    .seg_no,
    .dp_no,
    .an_no
  );

  assign beat_d = beat_q + 1'b1;
  always_ff @(posedge clk_i) begin
    if (!rst_n_view_q) beat_q <= '0;
    else        beat_q <= beat_d;
  end

  assign led_o = {10'd0, sticky_q[3], bypass, sticky_q[2:0], beat_q[HeartbeatBit]};

  // sw[11:2] are unused; core_busy, core_channel and core_channel_error only feed the assertions.
  logic unused_sw;
  assign unused_sw = ^{sw_i[11:2], core_busy, core_channel, core_channel_error};

`ifndef SYNTHESIS
  // The control FSM strobes the core only in StIdle, after the previous output: never while busy,
  // and only with a channel the core has; the output it waits for is of the frame's channel.
  always @(posedge clk_i) begin
    if (rst_n && core_strobe && core_busy) $error("basys3_top: core strobed while busy");
    if (rst_n && core_channel_error) $error("basys3_top: core strobed with a channel it lacks");
    if (rst_n && state_q == StCore && core_valid && core_channel != chan_q[ChannelWidth-1:0]) begin
      $error("basys3_top: core output of another channel");
    end
  end
`endif

endmodule
