// SPDX-License-Identifier: MIT
// Multiply-accumulate of the IIR core, written so that Yosys and Vivado map it onto one DSP48E1.
//
// Pipeline (MacLatency = 3 registers from operands to sum):
//   a_q, b_q   operand registers (DSP48E1 AREG = 1, BREG = 1)
//   m_q        product register  (MREG = 1), AWidth + BWidth bits, not sign-extended further
//   p_q        accumulator       (PREG = 1), AccWidth bits, wraps like the DSP48E1 P register
// A term presented on a_i/b_i in cycle t is in p_o from cycle t + 3. A term marked with
// first_i starts a new sum: P restarts from Preload (the rounding constant of the core) instead
// of its previous value, so rounding costs no extra cycle. A term marked with shift_i is added
// to P >>> ShiftBits (arithmetic) instead of P: the DSP48E1's Z = P >>> 17 (OPMODE Z = 110), so
// a sum can be split into a lo phase and a hi phase at no extra cycle. All registers reset
// synchronously (an asynchronous reset would keep the registers out of the DSP48E1).
`default_nettype none

module iir_mac #(
  parameter int AWidth   = 25,  // A operand width (DSP48E1 A port: at most 25)
  parameter int BWidth   = 18,  // B operand width (DSP48E1 B port: at most 18)
  parameter int AccWidth = 48,  // accumulator width (DSP48E1 P register: at most 48)
  parameter int PreloadBit = 0,  // a new sum starts at 2^PreloadBit (0 <= PreloadBit < AccWidth)
  parameter int ShiftBits  = 17  // shift_i adds to P >>> ShiftBits (DSP48E1: 17 only)
) (
  input  logic                       clk_i,
  input  logic                       rst_ni,
  input  logic signed [AWidth-1:0]   a_i,
  input  logic signed [BWidth-1:0]   b_i,
  input  logic                       first_i,  // start a new sum at 2^PreloadBit
  input  logic                       shift_i,  // add to P >>> ShiftBits instead of P
  output logic signed [AccWidth-1:0] p_o
);

  localparam int ProdWidth = AWidth + BWidth;
  localparam logic signed [AccWidth-1:0] PRELOAD = AccWidth'(1) << PreloadBit;

  // Elaboration checks //
  if (PreloadBit < 0 || PreloadBit >= AccWidth) begin : g_bad_preload
    $error("iir_mac: PreloadBit must lie in [0, AccWidth)");
  end
  if (ShiftBits < 1 || ShiftBits >= AccWidth) begin : g_bad_shift
    $error("iir_mac: ShiftBits must lie in [1, AccWidth)");
  end
  if (ProdWidth > AccWidth) begin : g_bad_acc
    $error("iir_mac: the product does not fit in the accumulator (AWidth + BWidth > AccWidth)");
  end

  logic signed [AWidth-1:0]    a_q;
  logic signed [BWidth-1:0]    b_q;
  logic signed [ProdWidth-1:0] m_d, m_q;
  logic signed [AccWidth-1:0]  p_base, p_d, p_q;
  // first_i and shift_i travel beside the operands so that they meet their own product at the
  // adder.
  logic                        first_a_q, first_m_q;
  logic                        shift_a_q, shift_m_q;

  // Multiply //
  // Operands keep their own widths; the context widens them to ProdWidth, which is what the
  // DSP48E1 multiplier does. Widening them by hand would make Yosys use several DSPs.
  assign m_d = a_q * b_q;

  // Accumulate //
  // The DSP48E1's Z multiplexer: the preload (C port), P, or P >>> 17.
  assign p_base = first_m_q ? PRELOAD :
                  shift_m_q ? p_q >>> ShiftBits :
                              p_q;
  assign p_d    = p_base + AccWidth'(m_q);
  assign p_o    = p_q;

  always_ff @(posedge clk_i) begin
    if (!rst_ni) begin
      a_q       <= '0;
      b_q       <= '0;
      m_q       <= '0;
      p_q       <= '0;
      first_a_q <= 1'b0;
      first_m_q <= 1'b0;
      shift_a_q <= 1'b0;
      shift_m_q <= 1'b0;
    end else begin
      a_q       <= a_i;
      b_q       <= b_i;
      m_q       <= m_d;
      p_q       <= p_d;
      first_a_q <= first_i;
      first_m_q <= first_a_q;
      shift_a_q <= shift_i;
      shift_m_q <= shift_a_q;
    end
  end

endmodule
