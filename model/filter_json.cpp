// SPDX-License-Identifier: MIT
#include "filter_json.h"

#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>

namespace flange::model {
namespace {

using nlohmann::json;

class Reader {
 public:
  explicit Reader(const std::filesystem::path& path) : path_(path) {
    std::ifstream in(path);
    if (!in) fail_file("cannot open the file");
    try {
      root_ = json::parse(in);
    } catch (const json::parse_error& error) {
      fail_file(fmt::format("not valid JSON ({})", error.what()));
    }
    if (!root_.is_object()) fail_file("the top level is not a JSON object");
  }

  [[noreturn]] void fail(const std::string& field, const std::string& what) const {
    throw FilterJsonError(fmt::format("{}: field '{}': {}", path_.string(), field, what));
  }
  [[noreturn]] void fail_file(const std::string& what) const {
    throw FilterJsonError(fmt::format("{}: {}", path_.string(), what));
  }

  const json& object(const json& parent, const std::string& parent_name,
                     const std::string& key) const {
    const std::string field = parent_name.empty() ? key : parent_name + "." + key;
    const auto it = parent.find(key);
    if (it == parent.end()) fail(field, "missing");
    return *it;
  }

  std::int64_t integer(const json& parent, const std::string& parent_name, const std::string& key,
                       std::int64_t lo, std::int64_t hi) const {
    const std::string field = parent_name.empty() ? key : parent_name + "." + key;
    const json& value = object(parent, parent_name, key);
    if (!value.is_number_integer()) fail(field, "expected an integer");
    const std::int64_t v = value.get<std::int64_t>();
    if (v < lo || v > hi) fail(field, fmt::format("{} is outside [{}, {}]", v, lo, hi));
    return v;
  }

  double number(const json& value, const std::string& field) const {
    if (!value.is_number()) fail(field, "expected a number");
    const double v = value.get<double>();
    if (!std::isfinite(v)) fail(field, "expected a finite number");
    return v;
  }

  std::vector<double> numbers(const json& parent, const std::string& key) const {
    const json& value = object(parent, "", key);
    if (!value.is_array() || value.empty()) fail(key, "expected a non-empty array of numbers");
    std::vector<double> out;
    for (std::size_t i = 0; i < value.size(); ++i) {
      out.push_back(number(value[i], fmt::format("{}[{}]", key, i)));
    }
    return out;
  }

  const json& root() const { return root_; }
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
  json root_;
};

std::string name_of(const Reader& reader) {
  const auto it = reader.root().find("name");
  if (it == reader.root().end()) return "iir";
  if (!it->is_string()) reader.fail("name", "expected a string");
  return it->get<std::string>();
}

}  // namespace

CoreConfig CoreConfig::channel_config(int channel) const {
  if (channel < 0 || channel >= num_channels) {
    throw std::out_of_range(
        fmt::format("core config: channel {} outside [0, {}]", channel, num_channels - 1));
  }
  CoreConfig one = *this;
  one.num_channels = 1;
  one.coef_sets = 1;
  const std::int64_t* words = channel_words(channel);
  one.rom.assign(words, words + rom_depth());
  return one;
}

namespace {

// A split coefficient's value: (H + W 2^-L) 2^-F.
double split_value(const CoreConfig& c, std::int64_t hi, std::int64_t lo) {
  return std::ldexp(static_cast<double>(hi), -c.coef_frac_bits) +
         std::ldexp(static_cast<double>(lo), -(c.coef_frac_bits + c.split_shift()));
}

}  // namespace

std::vector<double> CoreConfig::b_values(int k, int channel) const {
  const std::int64_t* words = channel_words(channel) + k * terms();
  std::vector<double> b;
  for (int i = 0; i <= section_order; ++i) b.push_back(split_value(*this, words[hi_b(i)], words[lo_b(i)]));
  return b;
}

std::vector<double> CoreConfig::a_values(int k, int channel) const {
  const std::int64_t* words = channel_words(channel) + k * terms();
  std::vector<double> a{1.0};
  // The ROM holds -a.
  for (int j = 1; j <= section_order; ++j) a.push_back(-split_value(*this, words[hi_a(j)], words[lo_a(j)]));
  return a;
}

std::vector<std::int64_t> CoreConfig::error_feedback(int k, int channel) const {
  const std::int64_t* words = channel_words(channel) + k * terms();
  std::vector<std::int64_t> e;
  for (int j = 1; j <= section_order; ++j) e.push_back(words[err(j)]);
  return e;
}

void validate_core_config(const CoreConfig& c) {
  auto bad = [](const std::string& field, const std::string& what) {
    throw std::invalid_argument(fmt::format("core config: {}: {}", field, what));
  };
  if (c.num_sections < 1) bad("num_sections", "must be >= 1");
  if (c.section_order < 1) bad("section_order", "must be >= 1");
  if (c.filter_order < 1 || c.filter_order > c.num_sections * c.section_order) {
    bad("filter_order", "must lie in [1, num_sections * section_order]");
  }
  if (c.sample_width < 2 || c.sample_width > 32) bad("sample_width", "must lie in [2, 32]");
  if (c.coef_width < 2 || c.coef_width > 32) bad("coef_width", "must lie in [2, 32]");
  if (c.feedback_shift < 0) bad("feedback_shift", "must be >= 0");
  if (c.coef_frac_bits < 1 || c.coef_frac_bits > c.sample_width + c.feedback_shift) {
    bad("coef_frac_bits", "must lie in [1, sample_width + feedback_shift] (rounding constant "
                          "2^(F-1); the error word fits the history's width)");
  }
  if (c.acc_width > 64 || c.acc_width < c.coef_frac_bits + c.sample_width + c.feedback_shift) {
    bad("acc_width", "must lie in [coef_frac_bits + sample_width + feedback_shift, 64]");
  }
  if (c.sample_width + c.feedback_shift + c.coef_width > c.acc_width) {
    bad("acc_width", "the product (sample_width + feedback_shift + coef_width) does not fit");
  }
  if (c.coef_frac_bits + c.split_shift() > c.acc_width) {
    bad("acc_width", "the lo phase's rounding constant 2^(F-1+L) does not fit");
  }
  if (c.num_channels < 1 || c.num_channels > kMaxCoreChannels) {
    bad("num_channels", fmt::format("must lie in [1, {}]", kMaxCoreChannels));
  }
  if (c.coef_sets != 1 && c.coef_sets != c.num_channels) {
    bad("coef_sets", "must be 1 or num_channels");
  }
  if (static_cast<std::int64_t>(c.rom.size()) !=
      std::int64_t{c.coef_sets} * c.rom_depth()) {
    bad("rom", fmt::format("holds {} words, expected coef_sets * num_sections * "
                           "(5 * section_order + 2) = {}",
                           c.rom.size(), std::int64_t{c.coef_sets} * c.rom_depth()));
  }
  const std::int64_t hi = (std::int64_t{1} << (c.coef_width - 1)) - 1;
  for (std::size_t i = 0; i < c.rom.size(); ++i) {
    if (c.rom[i] < -hi - 1 || c.rom[i] > hi) {
      bad(fmt::format("rom[{}]", i),
          fmt::format("{} does not fit {} bits", c.rom[i], c.coef_width));
    }
  }
  // Lo words are the low L bits of a split coefficient: in [0, 2^L).
  for (int set = 0; set < c.coef_sets; ++set) {
    for (int k = 0; k < c.num_sections; ++k) {
      const int base = set * c.rom_depth() + k * c.terms();
      for (int i = c.lo_b(0); i <= c.lo_a(c.section_order); ++i) {
        if (c.rom[static_cast<std::size_t>(base + i)] < 0) {
          bad(fmt::format("rom[{}]", base + i),
              fmt::format("{} is a lo word and must lie in [0, 2^{})",
                          c.rom[static_cast<std::size_t>(base + i)], c.split_shift()));
        }
      }
    }
  }
}

static CoreConfig load_core_config_unguarded(const std::filesystem::path& filter_json) {
  const Reader reader(filter_json);
  const json& q = reader.object(reader.root(), "", "quantized");
  if (!q.is_object()) reader.fail("quantized", "expected an object");

  CoreConfig c;
  c.name = name_of(reader);
  const std::string p = "quantized";
  c.sample_width = static_cast<int>(reader.integer(q, p, "data_bits", 2, 32));
  c.coef_width = static_cast<int>(reader.integer(q, p, "coef_bits", 2, 32));
  c.acc_width = static_cast<int>(reader.integer(q, p, "acc_bits", 2, 64));
  c.num_sections = static_cast<int>(reader.integer(q, p, "sections", 1, 1024));
  c.section_order = static_cast<int>(reader.integer(q, p, "section_order", 1, 64));
  c.coef_frac_bits = static_cast<int>(reader.integer(q, p, "coef_frac_bits", 1, 63));
  c.feedback_shift = static_cast<int>(reader.integer(q, p, "feedback_shift", 0, 63));
  c.filter_order = static_cast<int>(reader.integer(reader.root(), "", "order", 1, 1024));
  const std::int64_t split = reader.integer(q, p, "split_shift", 1, 63);
  if (split != c.split_shift()) {
    reader.fail("quantized.split_shift",
                fmt::format("{} is not coef_bits - 1 = {}", split, c.split_shift()));
  }
  if (c.coef_frac_bits > c.sample_width + c.feedback_shift) {
    reader.fail("quantized.coef_frac_bits", "must be at most data_bits + feedback_shift");
  }
  if (c.acc_width < c.coef_frac_bits + c.sample_width + c.feedback_shift) {
    reader.fail("quantized.acc_bits", "must be at least coef_frac_bits + data_bits + feedback_shift");
  }
  if (c.sample_width + c.feedback_shift + c.coef_width > c.acc_width) {
    reader.fail("quantized.acc_bits", "data_bits + feedback_shift + coef_bits does not fit");
  }
  if (c.filter_order > c.num_sections * c.section_order) {
    reader.fail("order", "exceeds quantized.sections * quantized.section_order");
  }
  const std::int64_t depth = reader.integer(q, p, "rom_depth", 1, 1 << 20);
  if (depth != c.rom_depth()) {
    reader.fail(
        "quantized.rom_depth",
        fmt::format("{} is not sections * (5 * section_order + 2) = {}", depth, c.rom_depth()));
  }
  // Written since multichannel cores; a set without them is one channel.
  if (q.contains("channels")) {
    c.num_channels = static_cast<int>(reader.integer(q, p, "channels", 1, kMaxCoreChannels));
  }
  if (q.contains("coef_sets")) {
    c.coef_sets = static_cast<int>(reader.integer(q, p, "coef_sets", 1, kMaxCoreChannels));
    if (c.coef_sets != 1 && c.coef_sets != c.num_channels) {
      reader.fail("quantized.coef_sets", fmt::format("{} is neither 1 nor quantized.channels ({})",
                                                     c.coef_sets, c.num_channels));
    }
  }
  const std::int64_t word_count = depth * c.coef_sets;
  const json& words = reader.object(q, p, "words");
  if (!words.is_array() || static_cast<std::int64_t>(words.size()) != word_count) {
    reader.fail("quantized.words", fmt::format("expected an array of {} integers (rom_depth {} x "
                                               "coef_sets {})",
                                               word_count, depth, c.coef_sets));
  }
  const std::int64_t hi = (std::int64_t{1} << (c.coef_width - 1)) - 1;
  for (std::size_t i = 0; i < words.size(); ++i) {
    const std::string field = fmt::format("quantized.words[{}]", i);
    if (!words[i].is_number_integer()) reader.fail(field, "expected an integer");
    const std::int64_t w = words[i].get<std::int64_t>();
    if (w < -hi - 1 || w > hi) {
      reader.fail(field, fmt::format("{} does not fit {} bits (coef_bits)", w, c.coef_width));
    }
    c.rom.push_back(w);
  }
  try {
    validate_core_config(c);
  } catch (const std::invalid_argument& error) {
    reader.fail_file(error.what());
  }
  return c;
}

CoreConfig load_core_config(const std::filesystem::path& filter_json) {
  // A field of the wrong type that no check names (an object where a number goes, ...) is
  // refused like any other bad field, never let through as a library exception.
  try {
    return load_core_config_unguarded(filter_json);
  } catch (const nlohmann::json::exception& error) {
    throw FilterJsonError(
        fmt::format("{}: a field has the wrong type ({})", filter_json.string(), error.what()));
  }
}

static FloatDesign load_float_design_unguarded(const std::filesystem::path& filter_json) {
  const Reader reader(filter_json);
  FloatDesign d;
  d.name = name_of(reader);
  d.fs_hz = reader.number(reader.object(reader.root(), "", "fs_hz"), "fs_hz");
  if (d.fs_hz <= 0.0) reader.fail("fs_hz", "must be > 0");
  if (const auto it = reader.root().find("fc_hz"); it != reader.root().end() && !it->is_null()) {
    d.fc_hz = reader.number(*it, "fc_hz");
    if (*d.fc_hz <= 0.0 || *d.fc_hz >= d.fs_hz / 2)
      reader.fail("fc_hz", "must lie in (0, fs_hz / 2)");
  }
  d.b = reader.numbers(reader.root(), "b");
  d.a = reader.numbers(reader.root(), "a");
  if (d.a[0] == 0.0) reader.fail("a[0]", "must not be 0");
  d.leftover_gain =
      reader.number(reader.object(reader.root(), "", "leftover_gain"), "leftover_gain");

  const json& sos = reader.object(reader.root(), "", "sos");
  if (!sos.is_array() || sos.empty()) reader.fail("sos", "expected a non-empty array of rows");
  for (std::size_t r = 0; r < sos.size(); ++r) {
    const std::string row_name = fmt::format("sos[{}]", r);
    if (!sos[r].is_array() || sos[r].size() != 6) {
      reader.fail(row_name, "expected 6 numbers b0 b1 b2 a0 a1 a2");
    }
    std::array<double, 6> row{};
    for (std::size_t i = 0; i < 6; ++i) {
      row[i] = reader.number(sos[r][i], fmt::format("{}[{}]", row_name, i));
    }
    if (row[3] == 0.0) reader.fail(row_name + "[3]", "a0 must not be 0");
    d.sos.push_back(row);
  }
  return d;
}

FloatDesign load_float_design(const std::filesystem::path& filter_json) {
  // A field of the wrong type that no check names (an object where a number goes, ...) is
  // refused like any other bad field, never let through as a library exception.
  try {
    return load_float_design_unguarded(filter_json);
  } catch (const nlohmann::json::exception& error) {
    throw FilterJsonError(
        fmt::format("{}: a field has the wrong type ({})", filter_json.string(), error.what()));
  }
}

FloatDesign load_float_design(const std::filesystem::path& filter_json, int channel) {
  FloatDesign design = load_float_design(filter_json);
  const Reader reader(filter_json);
  const auto sets = reader.root().find("channel_sets");
  if (sets == reader.root().end()) return design;
  if (!sets->is_array() || channel < 0 || channel >= static_cast<int>(sets->size())) {
    reader.fail("channel_sets", fmt::format("no set for channel {}", channel));
  }
  try {
    const json& set = (*sets)[static_cast<std::size_t>(channel)];
    const std::string name = fmt::format("channel_sets[{}]", channel);
    design.fc_hz = reader.number(reader.object(set, name, "fc_hz"), name + ".fc_hz");
    design.leftover_gain =
        reader.number(reader.object(set, name, "leftover_gain"), name + ".leftover_gain");
    design.sos.clear();
    for (const json& row : reader.object(set, name, "sos")) {
      std::array<double, 6> values{};
      for (std::size_t i = 0; i < 6; ++i) values[i] = reader.number(row.at(i), name + ".sos");
      if (values[3] == 0.0) reader.fail(name + ".sos", "a0 must not be 0");
      design.sos.push_back(values);
    }
    if (design.sos.empty()) reader.fail(name + ".sos", "expected a non-empty array of rows");
  } catch (const nlohmann::json::exception& error) {
    reader.fail(fmt::format("channel_sets[{}]", channel),
                fmt::format("wrong type ({})", error.what()));
  }
  return design;
}

double dc_group_delay_samples(const FloatDesign& design) {
  double delay = 0.0;
  for (const auto& row : design.sos) {
    auto centroid = [](double c0, double c1, double c2) {
      const double sum = c0 + c1 + c2;
      return sum == 0.0 ? 0.0 : (c1 + 2.0 * c2) / sum;
    };
    delay += centroid(row[0], row[1], row[2]) - centroid(row[3], row[4], row[5]);
  }
  return delay;
}

}  // namespace flange::model
