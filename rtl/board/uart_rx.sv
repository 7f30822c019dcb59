// SPDX-License-Identifier: MIT
// UART receiver, 8N1, LSB first: one byte strobe per frame, a stop-bit error strobe otherwise.
`default_nettype none

module uart_rx #(
  // Clock cycles per bit: 868 for 115200 baud at 100 MHz (0.01 % off); >= 4 (the start bit is
  // re-checked at half a bit, the data bits sampled at their middle).
  parameter int ClksPerBit = 868
) (
  input  logic       clk_i,
  input  logic       rst_ni,        // synchronous, active low
  input  logic       rx_i,          // asynchronous line, idle high
  output logic [7:0] data_o,
  output logic       data_valid_o,  // one cycle per received byte
  output logic       frame_err_o    // one cycle: the stop bit was low, the byte is dropped
);

  localparam int CntWidth = $clog2(ClksPerBit + 1);
  localparam logic [CntWidth-1:0] FULL_BIT = CntWidth'(ClksPerBit - 1);
  localparam logic [CntWidth-1:0] HALF_BIT = CntWidth'(ClksPerBit / 2 - 1);

  if (ClksPerBit < 4) begin : g_bad_clks_per_bit
    $error("uart_rx: ClksPerBit must be at least 4");
  end

  typedef enum logic [1:0] {StIdle, StStart, StData, StStop} state_e;

  // Two flip-flops against metastability (the line is asynchronous to clk_i).
  logic [1:0] sync_q, sync_d;
  logic       rx;
  assign sync_d = {sync_q[0], rx_i};
  assign rx     = sync_q[1];

  state_e              state_q, state_d;
  logic [CntWidth-1:0] cnt_q, cnt_d;
  logic [2:0]          bit_q, bit_d;
  logic [7:0]          shift_q, shift_d;
  logic                valid_q, valid_d;
  logic                err_q, err_d;

  always_comb begin
    state_d = state_q;
    cnt_d   = cnt_q;
    bit_d   = bit_q;
    shift_d = shift_q;
    valid_d = 1'b0;
    err_d   = 1'b0;
    unique case (state_q)
      StIdle: begin
        cnt_d = HALF_BIT;
        if (!rx) state_d = StStart;
      end
      StStart: begin
        if (cnt_q != '0) begin
          cnt_d = cnt_q - 1'b1;
        end else if (rx) begin
          state_d = StIdle;  // a glitch, not a start bit
        end else begin
          state_d = StData;
          cnt_d   = FULL_BIT;
          bit_d   = '0;
        end
      end
      StData: begin
        if (cnt_q != '0) begin
          cnt_d = cnt_q - 1'b1;
        end else begin
          shift_d = {rx, shift_q[7:1]};
          cnt_d   = FULL_BIT;
          bit_d   = bit_q + 1'b1;
          if (bit_q == 3'd7) state_d = StStop;
        end
      end
      StStop: begin
        if (cnt_q != '0) begin
          cnt_d = cnt_q - 1'b1;
        end else begin
          // Back to idle in the middle of the stop bit: a following start edge is not missed.
          state_d = StIdle;
          valid_d = rx;
          err_d   = !rx;
        end
      end
      default: state_d = StIdle;
    endcase
  end

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      sync_q  <= 2'b11;
      state_q <= StIdle;
      cnt_q   <= '0;
      bit_q   <= '0;
      shift_q <= '0;
      valid_q <= 1'b0;
      err_q   <= 1'b0;
    end else begin
      sync_q  <= sync_d;
      state_q <= state_d;
      cnt_q   <= cnt_d;
      bit_q   <= bit_d;
      shift_q <= shift_d;
      valid_q <= valid_d;
      err_q   <= err_d;
    end
  end

  assign data_o       = shift_q;
  assign data_valid_o = valid_q;
  assign frame_err_o  = err_q;

endmodule
