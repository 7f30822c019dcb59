// SPDX-License-Identifier: MIT
// A made-up module whose coverage points small.dat holds (the coverage report's own test).
module demo (input logic clk_i, input logic a_i, output logic [3:0] q_o);
  logic [3:0] q_q;
  logic [1:0] mem [2];
  always_ff @(posedge clk_i) begin
    if (a_i) q_q <= q_q + 1'b1;
    else q_q <= q_q;
  end
  always_comb begin
    unique case (q_q[0])
      1'b0: q_o = q_q;
      default: q_o = '0;
    endcase
  end
endmodule
