# SPDX-License-Identifier: MIT
# Builds the Basys-3 bitstream with Vivado in batch mode (non-project flow) from the same sources
# and constraints the Verilator and Yosys flows use (docs/board.md, "Program the board").
#
#   vivado -mode batch -source rtl/board/vivado_build.tcl -tclargs [COEFF_DIR] [OUT_DIR] [CLKS_PER_BIT]
#
# COEFF_DIR: coefficient set folder (default coeffs/measurement_sos; a multichannel set such as
# tests/data/coeffs/loco_ch12 gives a board with that many channels); OUT_DIR: where the bitstream
# and reports go (default build/vivado); CLKS_PER_BIT: 100 MHz / baud, the UART's rate (default 868,
# 115200 baud; 109 for 921600: docs/board.md, "Link budget"; `flange stream --baud` must match).
# Run from the repository root. Writes OUT_DIR/basys3_top.bit and the routed design's reports
# OUT_DIR/timing_summary.rpt (report_timing_summary) and OUT_DIR/utilization.rpt
# (report_utilization), which `flange synth --coeffs COEFF_DIR --vivado-report OUT_DIR` sets beside
# its pre-route estimate (docs/synthesis.md); exits non-zero when timing fails.

set root [file normalize [file join [file dirname [info script]] .. ..]]
set coeffs [file normalize [file join $root coeffs measurement_sos]]
set out [file normalize [file join $root build vivado]]
if {$argc >= 1} { set coeffs [file normalize [lindex $argv 0]] }
if {$argc >= 2} { set out [file normalize [lindex $argv 1]] }
set clks_per_bit 868
if {$argc >= 3} { set clks_per_bit [lindex $argv 2] }
file mkdir $out

set part xc7a35tcpg236-1
set board_sources {crc8.sv uart_rx.sv uart_tx.sv frame_decoder.sv frame_encoder.sv
                   clearance_display.sv seven_seg.sv button_debounce.sv basys3_top.sv}

# The package first: the core names iir_coeffs_pkg::X.
read_verilog -sv [file join $coeffs iir_coeffs_pkg.sv]
read_verilog -sv [list [file join $root rtl iir_mac.sv] [file join $root rtl iir_core.sv]]
foreach f $board_sources { read_verilog -sv [file join $root rtl board $f] }
read_xdc [file join $root rtl board basys3.xdc]

# The ROM image is read by $readmemh at elaboration: pass its absolute path.
synth_design -top basys3_top -part $part \
  -generic "RomFile=\"[file join $coeffs coeffs.mem]\"" -generic "ClksPerBit=$clks_per_bit"
report_utilization -file [file join $out utilization_synth.rpt]
opt_design
place_design
phys_opt_design
route_design
# The names flange synth --vivado-report reads (tb/synth/vivado_report.h).
report_utilization -file [file join $out utilization.rpt]
report_timing_summary -max_paths 10 -file [file join $out timing_summary.rpt]
report_drc -file [file join $out drc.rpt]
write_bitstream -force [file join $out basys3_top.bit]

# Timing must close at 100 MHz.
set wns [get_property SLACK [get_timing_paths -delay_type max -max_paths 1]]
puts "vivado_build: WNS $wns ns; bitstream [file join $out basys3_top.bit]"
if {$wns < 0} {
  puts "vivado_build: timing not met (WNS $wns ns)"
  exit 1
}
