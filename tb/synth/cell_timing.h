// SPDX-License-Identifier: MIT
// The delays of Yosys's xc7 cell models: the specify blocks of +/xilinx/cells_sim.v (from the
// prjxray database of the Artix-7), as Yosys elaborates them for each parameter set in use
// (`read_verilog -lib -specify`, then `sta`, then `write_rtlil`). Read from that RTLIL text the way
// Yosys's own `sta` reads them (kernel/timinginfo.h): the worst of rise and fall, conditions
// ignored.
#pragma once

#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace flange::tb {

// A port bit of a cell, written "PORT[bit]" ("I0[0]", "CO[3]").
using PinBit = std::string;
PinBit pin_bit(const std::string& port, int bit);

struct CombArc {
  PinBit to;
  int ps = 0;
};

// One cell model (one parameter set): its arcs in picoseconds.
struct CellTiming {
  std::string module;                             // "LUT6", "$paramod$...\\DSP48E1"
  std::string type;                               // the cell type: "LUT6", "DSP48E1"
  std::map<std::string, std::string> parameters;  // normalised (cell_parameter_value)
  std::set<std::string> inputs;                   // the input ports (the rest are outputs)
  std::map<PinBit, std::vector<CombArc>> comb;    // input bit -> outputs ($specify2)
  std::map<PinBit, int> clock_to_out;             // output bit -> clock edge to output
  std::map<PinBit, std::string> clock_of_output;  // output bit -> its clock port ("C")
  std::map<PinBit, int> setup;                    // input bit -> setup before the clock edge
  std::map<PinBit, std::string> clock_of_input;   // input bit -> its clock port
};

// The text does not hold the cell models the way write_rtlil writes them.
class CellTimingError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A parameter value in one form whatever its source: a Yosys JSON string of bits
// ("00000001"), an RTLIL constant (8'00000001) or decimal (1) all become the binary digits without
// leading zeros ("1"); a string ("DIRECT", or JSON's "DIRECT ") becomes its text.
std::string cell_parameter_value(const std::string& value);

class CellTimingLibrary {
 public:
  // Parses write_rtlil's text of the cell models; throws CellTimingError naming the line.
  static CellTimingLibrary parse(const std::string& rtlil_text);

  // The model of a cell of `type` with these (normalised) parameters: the elaborated module whose
  // parameters all agree, else the one module of that type; nullptr when the type has no model.
  const CellTiming* find(const std::string& type,
                         const std::map<std::string, std::string>& parameters) const;

  const std::vector<CellTiming>& cells() const { return cells_; }

 private:
  std::vector<CellTiming> cells_;
};

}  // namespace flange::tb
