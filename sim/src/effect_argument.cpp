// SPDX-License-Identifier: MIT
#include "effect_argument.h"

#include <fmt/format.h>

#include <charconv>

#include "sim_error.h"

namespace flange::sim {
namespace {

constexpr const char* kForm = "expected NAME or NAME:key=value[,key=value...]";

double parse_number(const std::string& text, const std::string& argument, const std::string& key) {
  double value = 0.0;
  const char* first = text.data();
  const char* last = first + text.size();
  if (!text.empty() && *first == '+') ++first;  // from_chars does not take a leading '+'
  const auto [end, error] = std::from_chars(first, last, value);
  if (text.empty() || error != std::errc() || end != last) {
    throw BadArgument(fmt::format("--effect '{}': {} = '{}' is not a number", argument, key, text));
  }
  return value;
}

}  // namespace

EffectArgument parse_effect_argument(const std::string& text) {
  EffectArgument argument;
  const std::size_t colon = text.find(':');
  argument.name = text.substr(0, colon);
  if (argument.name.empty()) throw BadArgument(fmt::format("--effect '{}': {}", text, kForm));
  if (colon == std::string::npos) return argument;
  const std::string pairs = text.substr(colon + 1);
  std::size_t start = 0;
  while (start <= pairs.size()) {
    const std::size_t comma = std::min(pairs.find(',', start), pairs.size());
    const std::string pair = pairs.substr(start, comma - start);
    const std::size_t equals = pair.find('=');
    if (equals == std::string::npos || equals == 0) {
      throw BadArgument(fmt::format("--effect '{}': '{}' is not key=value; {}", text, pair, kForm));
    }
    const std::string key = pair.substr(0, equals);
    if (argument.values.count(key) != 0) {
      throw BadArgument(fmt::format("--effect '{}': key '{}' is given twice", text, key));
    }
    argument.values[key] = parse_number(pair.substr(equals + 1), text, key);
    start = comma + 1;
  }
  return argument;
}

}  // namespace flange::sim
