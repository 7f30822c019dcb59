// SPDX-License-Identifier: MIT
#include "timing_estimate.h"

#include <fmt/format.h>

#include <algorithm>
#include <limits>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>

namespace flange::tb {

int TimingEstimate::worst_slack_ps() const {
  int worst = std::numeric_limits<int>::max();
  for (const ClockEstimate& c : clocks) worst = std::min(worst, c.slack_ps);
  return worst;
}

namespace {

using nlohmann::json;
constexpr int kNoArrival = std::numeric_limits<int>::min();

// A cell input pin that a net drives.
struct Sink {
  int cell = 0;
  PinBit pin;
};

struct Cell {
  std::string name, type, src;
  const CellTiming* timing = nullptr;
  std::map<PinBit, int> pins;  // port bit -> net (constants left out)
  std::set<PinBit> inputs;
};

// The netlist as the analysis needs it: cells with their models, and each net's driver and sinks.
struct Graph {
  std::vector<Cell> cells;
  std::map<int, std::pair<int, PinBit>> driver;  // net -> (cell, output pin)
  std::map<int, std::vector<Sink>> sinks;
  std::map<int, std::string> names;  // net -> RTL name, where Yosys kept one
  std::set<int> top_inputs;
  std::vector<std::string> types_without_model;
};

// A net's name: the public (non-$) Yosys name, preferring registers (`_q`) and short paths.
int name_rank(const std::string& name) {
  const std::string base = name.substr(0, name.find('['));
  const bool reg = base.size() > 2 && base.compare(base.size() - 2, 2, "_q") == 0;
  return (reg ? 0 : 1000) + static_cast<int>(std::count(name.begin(), name.end(), '.')) * 100 +
         static_cast<int>(name.size());
}

// The RTL name Yosys left inside a hidden name: "$techmap1$abc$2$lut\\err_raddr[0].A" ->
// "err_raddr[0]", "$abc$2$lut\\err_addr$func$..." -> "err_addr"; "" when there is none.
std::string name_hint(const std::string& hidden) {
  const std::size_t slash = hidden.rfind('\\');
  if (slash == std::string::npos) return "";
  std::string hint = hidden.substr(slash + 1);
  hint = hint.substr(0, hint.find('$'));
  if (hint.size() > 2 && hint[hint.size() - 2] == '.') hint.resize(hint.size() - 2);  // ".A"
  return hint;
}

void keep_name(std::map<int, std::string>& names, int net, const std::string& name) {
  auto it = names.find(net);
  if (it == names.end() || name_rank(name) < name_rank(it->second)) names[net] = name;
}

void read_names(const json& module, Graph& g) {
  std::map<int, std::string> hints;
  for (const auto& [name, net] : module.at("netnames").items()) {
    const bool hidden = net.value("hide_name", 0) != 0;
    const std::string base = hidden ? name_hint(name) : name;
    if (base.empty()) continue;
    const json& bits = net.at("bits");
    const int offset = net.value("offset", 0);
    for (std::size_t i = 0; i < bits.size(); ++i) {
      if (!bits[i].is_number()) continue;
      const std::string bit_name =
          bits.size() == 1 && offset == 0 ? base : fmt::format("{}[{}]", base, offset + int(i));
      keep_name(hidden ? hints : g.names, bits[i].get<int>(), hidden ? base : bit_name);
    }
  }
  // A net without a public name is called after the RTL signal it was made from, marked "~".
  for (const auto& [net, hint] : hints)
    if (!g.names.count(net)) g.names[net] = "~" + hint;
  for (const auto& [name, port] : module.at("ports").items()) {
    if (port.at("direction") != "input") continue;
    for (const json& bit : port.at("bits"))
      if (bit.is_number()) g.top_inputs.insert(bit.get<int>());
  }
}

Graph read_graph(const std::string& netlist_json, const std::string& top,
                 const CellTimingLibrary& library) {
  const json netlist = json::parse(netlist_json);
  const json& module = netlist.at("modules").at(top);
  Graph g;
  read_names(module, g);
  std::set<std::string> missing;
  for (const auto& [name, c] : module.at("cells").items()) {
    Cell cell;
    cell.name = name;
    cell.type = c.at("type").get<std::string>();
    if (c.contains("attributes")) cell.src = c["attributes"].value("src", "");
    std::map<std::string, std::string> parameters;
    if (c.contains("parameters"))
      for (const auto& [p, v] : c["parameters"].items())
        parameters[p] = cell_parameter_value(v.is_string() ? v.get<std::string>() : v.dump());
    cell.timing = library.find(cell.type, parameters);
    if (cell.timing == nullptr) missing.insert(cell.type);
    const int index = static_cast<int>(g.cells.size());
    for (const auto& [port, bits] : c.at("connections").items()) {
      // Yosys writes a cell's port directions only while its type's module is loaded.
      bool input = false;
      if (c.contains("port_directions")) {
        input = c["port_directions"].at(port) == "input";
      } else if (cell.timing != nullptr) {
        input = cell.timing->inputs.count(port) != 0;
      } else {
        throw TimingEstimateError(
            fmt::format("cell {} ({}): no port directions and no model", name, cell.type));
      }
      for (std::size_t i = 0; i < bits.size(); ++i) {
        if (!bits[i].is_number()) continue;
        const int net = bits[i].get<int>();
        const PinBit pin = pin_bit(port, static_cast<int>(i));
        cell.pins[pin] = net;
        if (input) {
          cell.inputs.insert(pin);
          g.sinks[net].push_back({index, pin});
        } else {
          g.driver[net] = {index, pin};
        }
      }
    }
    g.cells.push_back(std::move(cell));
  }
  g.types_without_model.assign(missing.begin(), missing.end());
  return g;
}

std::string port_of(const PinBit& pin) { return pin.substr(0, pin.find('[')); }

// A net that needs no general routing to this sink (NetAllowance::dedicated_connections).
bool dedicated(const Graph& g, int net, const Sink& sink) {
  auto d = g.driver.find(net);
  if (d == g.driver.end()) return false;
  const Cell& from = g.cells[d->second.first];
  const std::string& to_type = g.cells[sink.cell].type;
  const std::string to_port = port_of(sink.pin);
  const bool from_lut = from.type.rfind("LUT", 0) == 0;
  if (from.type == "CARRY4" && d->second.second == "CO[3]" && to_type == "CARRY4" &&
      to_port == "CI")
    return true;
  if (from_lut && to_type == "MUXF7" && to_port != "S") return true;
  if (from.type == "MUXF7" && to_type == "MUXF8" && to_port != "S") return true;
  return from_lut && to_type == "CARRY4" && (to_port == "S" || to_port == "DI") &&
         g.sinks.at(net).size() == 1;
}

int fanout(const Graph& g, int net) {
  auto it = g.sinks.find(net);
  return it == g.sinks.end() ? 0 : static_cast<int>(it->second.size());
}

int net_ps(const Graph& g, const NetAllowance& a, int net, const Sink& sink) {
  if (a.dedicated_connections && dedicated(g, net, sink)) return 0;
  return a.ps(fanout(g, net));
}

// How a net's latest arrival came about: launched by a register, or through a cell arc.
struct Arrival {
  int ps = kNoArrival;
  int cell = -1;    // the cell driving the net on the latest path
  PinBit from_pin;  // its input pin on that path ("" when the cell launched it)
  int from_net = -1;
  int cell_ps = 0;
  int net_ps = 0;  // allowance from from_net to from_pin
};

class Analysis {
 public:
  Analysis(const Graph& g, const NetAllowance& a) : g_(g), a_(a) {}

  const Arrival& arrival(int net) {
    auto it = memo_.find(net);
    if (it != memo_.end()) {
      if (it->second.second) return it->second.first;
      throw TimingEstimateError(
          fmt::format("a combinational loop runs through net {}", name_of(net)));
    }
    memo_[net] = {Arrival{}, false};
    Arrival best;
    auto d = g_.driver.find(net);
    if (d != g_.driver.end() && g_.cells[d->second.first].timing != nullptr) {
      const Cell& cell = g_.cells[d->second.first];
      const PinBit& out = d->second.second;
      auto launch = cell.timing->clock_to_out.find(out);
      if (launch != cell.timing->clock_to_out.end()) {
        best = Arrival{launch->second, d->second.first, "", -1, launch->second, 0};
      }
      for (const PinBit& in : cell.inputs) {
        auto arcs = cell.timing->comb.find(in);
        if (arcs == cell.timing->comb.end()) continue;
        for (const CombArc& arc : arcs->second) {
          if (arc.to != out) continue;
          const int src = cell.pins.at(in);
          const Arrival& a = arrival(src);
          if (a.ps == kNoArrival) continue;
          const int wire = net_ps(g_, a_, src, Sink{d->second.first, in});
          if (a.ps + wire + arc.ps > best.ps) {
            best = Arrival{a.ps + wire + arc.ps, d->second.first, in, src, arc.ps, wire};
          }
        }
      }
    }
    memo_[net] = {best, true};
    return memo_[net].first;
  }

  // The net's RTL name, else where its driver comes from in the RTL ("iir_core.sv:284").
  std::string name_of(int net) const {
    auto it = g_.names.find(net);
    if (it != g_.names.end()) return it->second;
    auto d = g_.driver.find(net);
    if (d == g_.driver.end()) return "(unnamed)";
    const Cell& cell = g_.cells[d->second.first];
    if (!cell.name.empty() && cell.name[0] != '$')
      return "~" + cell.name.substr(0, cell.name.find('.'));
    const std::size_t sv = cell.src.find(".sv:");
    if (sv != std::string::npos) {
      const std::size_t start = cell.src.find_last_of('/', sv) + 1;
      const std::size_t end = cell.src.find('.', sv + 4);
      return "@" + cell.src.substr(start, end - start);
    }
    return "(unnamed)";
  }

 private:
  const Graph& g_;
  const NetAllowance& a_;
  std::map<int, std::pair<Arrival, bool>> memo_;
};

// The top-level port a clock pin's net comes from, through the buffers (BUFG, IBUF).
std::string clock_name(const Graph& g, int net) {
  for (int hops = 0; hops < 8; ++hops) {
    if (g.top_inputs.count(net)) break;
    auto d = g.driver.find(net);
    if (d == g.driver.end()) break;
    const Cell& buffer = g.cells[d->second.first];
    if (buffer.inputs.size() != 1) break;
    net = buffer.pins.at(*buffer.inputs.begin());
  }
  auto it = g.names.find(net);
  return it == g.names.end() ? fmt::format("net {}", net) : it->second;
}

// A register input with a setup time: where a path ends.
struct Endpoint {
  int cell = 0;
  PinBit pin;
  int net = 0;
  int setup_ps = 0;
  std::string clock;
};

std::vector<Endpoint> endpoints(const Graph& g) {
  std::vector<Endpoint> ends;
  for (std::size_t c = 0; c < g.cells.size(); ++c) {
    const Cell& cell = g.cells[c];
    if (cell.timing == nullptr) continue;
    for (const auto& [pin, setup] : cell.timing->setup) {
      auto net = cell.pins.find(pin);
      auto clock_port = cell.timing->clock_of_input.find(pin);
      if (net == cell.pins.end() || clock_port == cell.timing->clock_of_input.end()) continue;
      auto clock_net = cell.pins.find(pin_bit(clock_port->second, 0));
      if (clock_net == cell.pins.end()) continue;
      ends.push_back(
          {static_cast<int>(c), pin, net->second, setup, clock_name(g, clock_net->second)});
    }
  }
  return ends;
}

// The register a cell holds: the RTL name of an output, else the memory's name on its cells
// ("err_ram.0.2": the memory err_ram), else the name Yosys derived for an output.
std::string register_name(const Graph& g, int cell_index) {
  const Cell& cell = g.cells[cell_index];
  std::string derived;
  for (const auto& [pin, net] : cell.pins) {
    auto name = g.names.find(net);
    if (cell.inputs.count(pin) || name == g.names.end()) continue;
    if (name->second.front() != '~') return name->second;
    if (derived.empty()) derived = name->second;
  }
  if (!cell.name.empty() && cell.name[0] != '$') return cell.name.substr(0, cell.name.find('.'));
  return derived.empty() ? cell.type + " " + cell.name : derived;
}

std::string arc_name(const PinBit& from, const PinBit& to) {
  return fmt::format("{}->{}", port_of(from), port_of(to));
}

TimingPath trace(const Graph& g, Analysis& analysis, const Endpoint& end, int period_ps,
                 const NetAllowance& allowance) {
  TimingPath path;
  path.clock = end.clock;
  path.to = register_name(g, end.cell);
  path.to_pin = g.cells[end.cell].type + " " + port_of(end.pin);
  path.setup_ps = end.setup_ps;
  int net = end.net;
  int wire = net_ps(g, allowance, net, Sink{end.cell, end.pin});
  std::vector<PathStep> reversed;
  while (net >= 0) {
    const Arrival& a = analysis.arrival(net);
    const Cell& cell = g.cells[a.cell];
    const PinBit out = g.driver.at(net).second;
    PathStep step{cell.name,
                  cell.type,
                  a.from_pin.empty() ? "clock->" + port_of(out) : arc_name(a.from_pin, out),
                  a.cell_ps,
                  analysis.name_of(net),
                  fanout(g, net),
                  wire};
    reversed.push_back(step);
    if (a.from_pin.empty()) {
      path.from = analysis.name_of(net);
      break;
    }
    wire = a.net_ps;
    net = a.from_net;
  }
  path.steps.assign(reversed.rbegin(), reversed.rend());
  for (const PathStep& s : path.steps) {
    path.cells_ps += s.cell_ps;
    path.nets_ps += s.net_ps;
  }
  path.cells_ps += path.setup_ps;
  path.logic_levels = static_cast<int>(path.steps.size()) - 1;
  path.slack_ps = period_ps - path.total_ps();
  return path;
}

}  // namespace

TimingEstimate estimate_timing(const std::string& netlist_json, const std::string& top,
                               const CellTimingLibrary& library, int period_ps,
                               const NetAllowance& allowance, int max_paths) {
  Graph g;
  try {
    g = read_graph(netlist_json, top, library);
  } catch (const nlohmann::json::exception& e) {
    throw TimingEstimateError("the netlist of " + top + " cannot be read: " + e.what());
  }
  TimingEstimate result;
  result.types_without_model = g.types_without_model;
  NetAllowance cells_only = allowance;
  cells_only.base_ps = 0;
  cells_only.per_fanout_ps = 0;
  Analysis with_nets(g, allowance), without_nets(g, cells_only);
  std::map<std::string, ClockEstimate> clocks;
  std::vector<std::pair<int, Endpoint>> timed;  // (arrival + allowance + setup, endpoint)
  for (const Endpoint& end : endpoints(g)) {
    const Arrival& a = with_nets.arrival(end.net);
    if (a.ps == kNoArrival)
      continue;  // driven from the pins or constants: not register to register
    const int total = a.ps + net_ps(g, allowance, end.net, Sink{end.cell, end.pin}) + end.setup_ps;
    const int cells = without_nets.arrival(end.net).ps + end.setup_ps;
    ClockEstimate& c = clocks[end.clock];
    c.clock = end.clock;
    c.period_ps = period_ps;
    c.worst_ps = std::max(c.worst_ps, total);
    c.worst_cells_ps = std::max(c.worst_cells_ps, cells);
    c.endpoints += 1;
    timed.emplace_back(total, end);
  }
  for (auto& [name, c] : clocks) {
    c.slack_ps = c.period_ps - c.worst_ps;
    result.clocks.push_back(c);
  }
  std::stable_sort(timed.begin(), timed.end(),
                   [](const auto& x, const auto& y) { return x.first > y.first; });
  // One path per register (a bus's bits share their worst path's shape).
  std::set<std::string> registers;
  for (const auto& [total, end] : timed) {
    if (static_cast<int>(result.worst_paths.size()) == max_paths) break;
    const std::string reg = register_name(g, end.cell);
    if (!registers.insert(reg.substr(0, reg.find('['))).second) continue;
    result.worst_paths.push_back(trace(g, with_nets, end, period_ps, allowance));
  }
  return result;
}

}  // namespace flange::tb
