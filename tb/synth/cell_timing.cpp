// SPDX-License-Identifier: MIT
#include "cell_timing.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <sstream>
#include <utility>

namespace flange::tb {

PinBit pin_bit(const std::string& port, int bit) { return fmt::format("{}[{}]", port, bit); }

namespace {

bool is_binary(const std::string& s) {
  return !s.empty() && s.find_first_not_of("01xz") == std::string::npos;
}

std::string strip_leading_zeros(const std::string& bits) {
  const std::size_t first = bits.find_first_not_of('0');
  return first == std::string::npos ? "0" : bits.substr(first);
}

// Decimal digits to binary digits (parameters up to 64 bits).
std::string decimal_to_binary(const std::string& digits) {
  unsigned long long v = std::stoull(digits);
  if (v == 0) return "0";
  std::string bits;
  for (; v != 0; v >>= 1) bits.insert(bits.begin(), (v & 1) ? '1' : '0');
  return bits;
}

// "\\O" -> "O"; "$x" stays.
std::string wire_name(const std::string& token) {
  return !token.empty() && token[0] == '\\' ? token.substr(1) : token;
}

// The cell type a module elaborates: "\\LUT6" -> LUT6, "$paramod\\LUT4\\INIT=..." -> LUT4,
// "$paramod$<sha1>\\DSP48E1" -> DSP48E1.
std::string module_type(const std::string& module) {
  if (module.rfind("$paramod$", 0) == 0) return module.substr(module.find('\\') + 1);
  if (module.rfind("$paramod\\", 0) == 0) {
    const std::size_t start = module.find('\\') + 1;
    return module.substr(start, module.find('\\', start) - start);
  }
  return wire_name(module);
}

std::vector<std::string> split_words(const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> words;
  for (std::string w; in >> w;) words.push_back(w);
  return words;
}

// One cell being read: its type, parameters and connections as text.
struct RawCell {
  std::string type;
  std::map<std::string, std::string> parameters;
  std::map<std::string, std::string> connections;
};

struct ModuleText {
  std::string name;
  std::map<std::string, std::string> parameters;
  std::map<std::string, int> widths;  // wire -> width
  std::set<std::string> inputs;
  std::vector<RawCell> cells;
};

// A parameter line "parameter [signed|real] \\NAME value" -> (NAME, value text).
std::pair<std::string, std::string> parse_parameter(const std::string& line, int line_no) {
  std::istringstream in(line);
  std::string keyword, name;
  in >> keyword >> name;
  while (name == "signed" || name == "real") in >> name;
  std::string value;
  std::getline(in, value);
  value.erase(0, value.find_first_not_of(' '));
  if (name.empty() || value.empty()) {
    throw CellTimingError(fmt::format("line {}: parameter without a name or value", line_no));
  }
  return {wire_name(name), value};
}

// The port bits of a signal such as `\\O [0]`, `\\A`, `\\A [3:1]`, `{ \\B \\A [0] }`, LSB first;
// constant bits are left out.
std::vector<PinBit> parse_signal(const std::string& text, const ModuleText& module, int line_no) {
  std::vector<std::string> words = split_words(text);
  // A concatenation lists its parts MSB first.
  std::vector<std::vector<PinBit>> parts;
  for (std::size_t i = 0; i < words.size(); ++i) {
    const std::string& w = words[i];
    if (w == "{" || w == "}") continue;
    if (w.find('\'') != std::string::npos || std::isdigit(static_cast<unsigned char>(w[0]))) {
      parts.emplace_back();  // a constant drives no port bit
      continue;
    }
    const std::string name = wire_name(w);
    auto width = module.widths.find(name);
    if (width == module.widths.end()) {
      throw CellTimingError(
          fmt::format("line {}: {} is not a wire of {}", line_no, name, module.name));
    }
    int lo = 0, hi = width->second - 1;
    if (i + 1 < words.size() && words[i + 1].front() == '[') {
      ++i;
      const std::string range = words[i].substr(1, words[i].size() - 2);
      const std::size_t colon = range.find(':');
      hi = std::stoi(range.substr(0, colon));
      lo = colon == std::string::npos ? hi : std::stoi(range.substr(colon + 1));
    }
    std::vector<PinBit> bits;
    for (int b = lo; b <= hi; ++b) bits.push_back(pin_bit(name, b));
    parts.push_back(bits);
  }
  std::vector<PinBit> bits;
  for (auto it = parts.rbegin(); it != parts.rend(); ++it)
    bits.insert(bits.end(), it->begin(), it->end());
  return bits;
}

int parameter_int(const RawCell& cell, const char* name) {
  auto it = cell.parameters.find(name);
  if (it == cell.parameters.end()) return 0;
  const std::size_t tick = it->second.find('\'');
  if (tick == std::string::npos) return std::stoi(it->second);
  const std::string bits = it->second.substr(tick + 1);
  // An undefined delay (32'x: the model gives none for this configuration) is no arc.
  if (bits.find_first_not_of("01") != std::string::npos) return -1;
  return static_cast<int>(std::stoll(bits, nullptr, 2));
}

// A module's specify cells as arcs (as kernel/timinginfo.h reads them).
CellTiming timing_of(const ModuleText& module, const std::vector<int>& cell_lines) {
  CellTiming t;
  t.module = module.name;
  t.type = module_type(module.name);
  t.inputs = module.inputs;
  for (const auto& [name, value] : module.parameters)
    t.parameters[name] = cell_parameter_value(value);
  for (std::size_t c = 0; c < module.cells.size(); ++c) {
    const RawCell& cell = module.cells[c];
    const int line_no = cell_lines[c];
    auto signal = [&](const char* port) {
      auto it = cell.connections.find(port);
      if (it == cell.connections.end()) {
        throw CellTimingError(fmt::format("line {}: {} has no {}", line_no, cell.type, port));
      }
      return parse_signal(it->second, module, line_no);
    };
    if (cell.type == "$specify2") {
      const int ps = std::max(parameter_int(cell, "T_RISE_MAX"), parameter_int(cell, "T_FALL_MAX"));
      const std::vector<PinBit> src = signal("SRC"), dst = signal("DST");
      if (ps < 0) continue;
      if (parameter_int(cell, "FULL") != 0) {
        for (const PinBit& s : src)
          for (const PinBit& d : dst) t.comb[s].push_back({d, ps});
      } else {
        for (std::size_t i = 0; i < std::min(src.size(), dst.size()); ++i)
          t.comb[src[i]].push_back({dst[i], ps});
      }
    } else if (cell.type == "$specify3") {
      const int ps = std::max(parameter_int(cell, "T_RISE_MAX"), parameter_int(cell, "T_FALL_MAX"));
      const std::vector<PinBit> clock = signal("SRC");
      if (ps <= 0 || clock.empty()) continue;
      for (const PinBit& d : signal("DST")) {
        t.clock_to_out[d] = std::max(t.clock_to_out[d], ps);
        t.clock_of_output[d] = clock.front().substr(0, clock.front().find('['));
      }
    } else if (cell.type == "$specrule") {
      const std::string type = cell.parameters.count("TYPE") ? cell.parameters.at("TYPE") : "";
      if (type != "\"$setup\"" && type != "\"$setuphold\"") continue;
      const std::vector<PinBit> clock = signal("DST");
      if (clock.empty()) continue;
      // A negative setup (the flip-flop's D: -46 ps, entered as 0) counts as none.
      const int ps = std::max(0, parameter_int(cell, "T_LIMIT_MAX"));
      for (const PinBit& s : signal("SRC")) {
        t.setup[s] = std::max(t.setup.count(s) ? t.setup[s] : 0, ps);
        t.clock_of_input[s] = clock.front().substr(0, clock.front().find('['));
      }
    }
  }
  return t;
}

bool same_arcs(const CellTiming& a, const CellTiming& b) {
  auto comb_equal = [](const auto& x, const auto& y) {
    if (x.size() != y.size()) return false;
    for (const auto& [from, arcs] : x) {
      auto it = y.find(from);
      if (it == y.end() || it->second.size() != arcs.size()) return false;
      for (std::size_t i = 0; i < arcs.size(); ++i)
        if (arcs[i].to != it->second[i].to || arcs[i].ps != it->second[i].ps) return false;
    }
    return true;
  };
  return comb_equal(a.comb, b.comb) && a.clock_to_out == b.clock_to_out && a.setup == b.setup;
}

}  // namespace

std::string cell_parameter_value(const std::string& value) {
  std::string v = value;
  if (v.size() >= 2 && v.front() == '"' && v.back() == '"') return v.substr(1, v.size() - 2);
  const std::size_t tick = v.find('\'');
  if (tick != std::string::npos && is_binary(v.substr(tick + 1))) {
    return strip_leading_zeros(v.substr(tick + 1));
  }
  if (is_binary(v)) return strip_leading_zeros(v);
  if (!v.empty() && v.find_first_not_of("0123456789") == std::string::npos) {
    return decimal_to_binary(v);
  }
  // Yosys's JSON marks a string that looks like bits with a trailing space.
  while (!v.empty() && v.back() == ' ') v.pop_back();
  return v;
}

CellTimingLibrary CellTimingLibrary::parse(const std::string& rtlil_text) {
  CellTimingLibrary library;
  std::istringstream lines(rtlil_text);
  std::string line;
  std::vector<std::string> blocks;  // module, cell, process, switch: each closed by `end`
  ModuleText module;
  std::vector<int> cell_lines;
  for (int line_no = 1; std::getline(lines, line); ++line_no) {
    const std::vector<std::string> words = split_words(line);
    if (words.empty() || words[0] == "attribute" || words[0] == "autoidx") continue;
    const std::string& kw = words[0];
    if (kw == "module") {
      if (!blocks.empty())
        throw CellTimingError(fmt::format("line {}: module inside a block", line_no));
      module = ModuleText{words.size() > 1 ? words[1] : "", {}, {}, {}, {}};
      cell_lines.clear();
      blocks.push_back(kw);
    } else if (kw == "cell" || kw == "process" || kw == "switch") {
      if (blocks.empty())
        throw CellTimingError(fmt::format("line {}: {} outside a module", line_no, kw));
      if (kw == "cell" && blocks.size() == 1) {
        module.cells.push_back({words.size() > 1 ? words[1] : "", {}, {}});
        cell_lines.push_back(line_no);
      }
      blocks.push_back(kw);
    } else if (kw == "end") {
      if (blocks.empty())
        throw CellTimingError(fmt::format("line {}: `end` without a block", line_no));
      blocks.pop_back();
      if (blocks.empty()) library.cells_.push_back(timing_of(module, cell_lines));
    } else if (blocks.size() == 1 && kw == "wire") {
      int width = 1;
      for (std::size_t i = 1; i + 1 < words.size(); ++i)
        if (words[i] == "width") width = std::stoi(words[i + 1]);
      module.widths[wire_name(words.back())] = width;
      if (std::find(words.begin(), words.end(), "input") != words.end())
        module.inputs.insert(wire_name(words.back()));
    } else if (blocks.size() == 1 && kw == "parameter") {
      module.parameters.insert(parse_parameter(line, line_no));
    } else if (blocks.size() == 2 && blocks.back() == "cell" && kw == "parameter") {
      module.cells.back().parameters.insert(parse_parameter(line, line_no));
    } else if (blocks.size() == 2 && blocks.back() == "cell" && kw == "connect") {
      std::istringstream in(line);
      std::string connect, port, rest;
      in >> connect >> port;
      std::getline(in, rest);
      module.cells.back().connections[wire_name(port)] = rest;
    }
  }
  if (!blocks.empty()) throw CellTimingError("the text ends inside a " + blocks.back());
  return library;
}

const CellTiming* CellTimingLibrary::find(
    const std::string& type, const std::map<std::string, std::string>& parameters) const {
  std::vector<const CellTiming*> of_type;
  for (const CellTiming& c : cells_)
    if (c.type == type) of_type.push_back(&c);
  if (of_type.empty()) return nullptr;
  const CellTiming* match = nullptr;
  for (const CellTiming* c : of_type) {
    const bool agrees = std::all_of(parameters.begin(), parameters.end(), [&](const auto& p) {
      auto it = c->parameters.find(p.first);
      return it == c->parameters.end() || it->second == p.second;
    });
    // An elaborated module ($paramod) is the instance's own; the generic one only a fallback.
    if (agrees && (match == nullptr || c->module.rfind("$paramod", 0) == 0)) match = c;
  }
  if (match != nullptr) return match;
  const bool all_same = std::all_of(of_type.begin(), of_type.end(), [&](const CellTiming* c) {
    return same_arcs(*c, *of_type[0]);
  });
  return all_same ? of_type[0] : nullptr;
}

}  // namespace flange::tb
