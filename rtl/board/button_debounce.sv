// SPDX-License-Identifier: MIT
// Push-button synchroniser and debouncer: the output follows the button once it has read the same
// level for 2^StableBits cycles. No reset input: it is what makes the board's reset.
`default_nettype none

module button_debounce #(
  // 20: 10.5 ms at 100 MHz, longer than the Basys-3 buttons bounce.
  parameter int StableBits = 20
) (
  input  logic clk_i,
  input  logic btn_i,   // asynchronous, active high
  output logic btn_o    // synchronous, debounced
);

  // Registers power up at 0 on the FPGA (and in Verilator): button released.
  logic [1:0]            sync_q, sync_d;
  logic [StableBits-1:0] cnt_q, cnt_d;
  logic                  state_q, state_d;

  assign sync_d = {sync_q[0], btn_i};

  always_comb begin
    cnt_d   = '0;
    state_d = state_q;
    if (sync_q[1] != state_q) begin
      cnt_d = cnt_q + 1'b1;
      if (&cnt_q) state_d = sync_q[1];
    end
  end

  always_ff @(posedge clk_i) begin
    sync_q  <= sync_d;
    cnt_q   <= cnt_d;
    state_q <= state_d;
  end

  assign btn_o = state_q;

endmodule
