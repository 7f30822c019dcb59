// SPDX-License-Identifier: MIT
#include "locomotive_manifest.h"

#include <fmt/format.h>

#include <algorithm>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <stdexcept>

#include "input_error.h"
#include "input_notes.h"

namespace flange::host {
namespace {

using nlohmann::json;

const std::set<std::string> top_level_fields = {"generated_by", "channels"};
const std::set<std::string> channel_fields = {"channel", "axle", "side", "file", "calibration"};

// A value as a message may echo it.
std::string shown(const json& value) { return printable_excerpt(value.dump()); }

void note_unknown_keys(const std::string& path, const json& object, const std::string& where,
                       const std::set<std::string>& known) {
  for (const auto& [key, value] : object.items()) {
    if (known.count(key) == 0) {
      note_input(fmt::format("{}: ignoring field {}{}: not a manifest field", path, where,
                             printable_excerpt(key)));
    }
  }
}

// A whole number in [low, high] at entry[key]; `where` is e.g. "channels[3]".
int whole_field(const std::string& path, const json& entry, const std::string& where,
                const char* key, int low, int high) {
  if (!entry.contains(key)) {
    throw InputError(fmt::format("{}: field {}.{} is missing; valid range {} to {}", path, where,
                                 key, low, high));
  }
  const json& value = entry[key];
  if (!value.is_number_integer() || value.get<std::int64_t>() < low ||
      value.get<std::int64_t>() > high) {
    throw InputError(
        fmt::format("{}: field {}.{}: {} is outside its valid range: a whole number "
                    "{} to {}",
                    path, where, key, shown(value), low, high));
  }
  return value.get<int>();
}

ManifestSide side_field(const std::string& path, const json& entry, const std::string& where) {
  const json* value = entry.contains("side") ? &entry["side"] : nullptr;
  if (value != nullptr && *value == "left") return ManifestSide::kLeft;
  if (value != nullptr && *value == "right") return ManifestSide::kRight;
  throw InputError(fmt::format("{}: field {}.side: {} is not a side; valid: \"left\" or \"right\"",
                               path, where, value != nullptr ? shown(*value) : "missing"));
}

// The channel's file, which must exist beside the manifest (or where its path says).
void file_field(const std::string& path, const json& entry, const std::string& where,
                ManifestChannel& channel) {
  if (!entry.contains("file") || !entry["file"].is_string() ||
      entry["file"].get<std::string>().empty()) {
    throw InputError(fmt::format(
        "{}: field {}.file: {} is not a file name; valid: a path relative to the manifest's folder",
        path, where, entry.contains("file") ? shown(entry["file"]) : "missing"));
  }
  channel.file = entry["file"].get<std::string>();
  channel.path = std::filesystem::path(path).parent_path() / channel.file;
  std::error_code error;
  if (!std::filesystem::is_regular_file(channel.path, error)) {
    throw InputError(fmt::format("{}: field {}.file: {} does not exist", path, where,
                                 printable_excerpt(channel.path.string(), 200)));
  }
}

// The wheel's calibration, optional; when given it must exist (relative to the manifest's folder).
void calibration_field(const std::string& path, const json& entry, const std::string& where,
                       ManifestChannel& channel) {
  if (!entry.contains("calibration")) return;
  if (!entry["calibration"].is_string() || entry["calibration"].get<std::string>().empty()) {
    throw InputError(fmt::format(
        "{}: field {}.calibration: {} is not a file name; valid: the wheel's model.json, a path "
        "relative to the manifest's folder",
        path, where, shown(entry["calibration"])));
  }
  channel.calibration = entry["calibration"].get<std::string>();
  channel.calibration_path = std::filesystem::path(path).parent_path() / channel.calibration;
  std::error_code error;
  if (!std::filesystem::is_regular_file(channel.calibration_path, error)) {
    throw InputError(fmt::format("{}: field {}.calibration: {} does not exist", path, where,
                                 printable_excerpt(channel.calibration_path.string(), 200)));
  }
}

ManifestChannel channel_entry(const std::string& path, const json& entry, std::size_t index) {
  const std::string where = fmt::format("channels[{}]", index);
  if (!entry.is_object()) {
    throw InputError(
        fmt::format("{}: field {}: {} is not an object with channel, axle, side and "
                    "file",
                    path, where, shown(entry)));
  }
  note_unknown_keys(path, entry, where + ".", channel_fields);
  ManifestChannel channel;
  channel.channel = whole_field(path, entry, where, "channel", 0, kManifestMaxChannels - 1);
  channel.axle = whole_field(path, entry, where, "axle", 1, kManifestAxles);
  channel.side = side_field(path, entry, where);
  file_field(path, entry, where, channel);
  calibration_field(path, entry, where, channel);
  return channel;
}

// Each channel, wheel and file once.
void check_unique(const std::string& path, const std::vector<ManifestChannel>& channels) {
  std::map<int, std::size_t> channel_at;
  std::map<std::string, std::size_t> wheel_at;
  std::map<std::filesystem::path, std::size_t> file_at;
  for (std::size_t k = 0; k < channels.size(); ++k) {
    const ManifestChannel& c = channels[k];
    if (const auto [it, fresh] = channel_at.emplace(c.channel, k); !fresh) {
      throw InputError(
          fmt::format("{}: field channels[{}].channel: {} is already channels[{}]'s; "
                      "each channel 0 to {} at most once",
                      path, k, c.channel, it->second, kManifestMaxChannels - 1));
    }
    if (const auto [it, fresh] = wheel_at.emplace(wheel_label(c), k); !fresh) {
      throw InputError(
          fmt::format("{}: field channels[{}]: {} is already channels[{}]'s wheel; "
                      "each wheel at most once",
                      path, k, wheel_label(c), it->second));
    }
    if (const auto [it, fresh] = file_at.emplace(c.path.lexically_normal(), k); !fresh) {
      throw InputError(
          fmt::format("{}: field channels[{}].file: {} is already channels[{}]'s "
                      "file; one file per channel",
                      path, k, printable_excerpt(c.file), it->second));
    }
  }
}

LocomotiveManifest manifest_from_json(const std::string& path, const json& document) {
  if (!document.is_object()) {
    throw InputError(
        fmt::format("{}: not a manifest: expected a JSON object with a channels array", path));
  }
  note_unknown_keys(path, document, "", top_level_fields);
  if (!document.contains("channels") || !document["channels"].is_array() ||
      document["channels"].empty() || document["channels"].size() > kManifestMaxChannels) {
    const json* channels = document.contains("channels") ? &document["channels"] : nullptr;
    const std::string found = channels == nullptr    ? "missing"
                              : channels->is_array() ? fmt::format("{} entries", channels->size())
                                                     : shown(*channels);
    throw InputError(fmt::format("{}: field channels: {}; valid: an array of 1 to {} channels",
                                 path, found, kManifestMaxChannels));
  }
  LocomotiveManifest manifest;
  manifest.path = path;
  const json& channels = document["channels"];
  for (std::size_t k = 0; k < channels.size(); ++k) {
    manifest.channels.push_back(channel_entry(path, channels[k], k));
  }
  check_unique(path, manifest.channels);
  std::sort(
      manifest.channels.begin(), manifest.channels.end(),
      [](const ManifestChannel& a, const ManifestChannel& b) { return a.channel < b.channel; });
  return manifest;
}

}  // namespace

const char* manifest_side_name(ManifestSide side) {
  return side == ManifestSide::kLeft ? "left" : "right";
}

std::string wheel_label(const ManifestChannel& channel) {
  return fmt::format("axle {} {}", channel.axle, manifest_side_name(channel.side));
}

std::string channel_file_name(int channel) { return fmt::format("channel_{:02d}.csv", channel); }

LocomotiveManifest load_locomotive_manifest(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) throw InputError(fmt::format("{}: cannot open the manifest", path));
  json document;
  try {
    document = json::parse(file);
  } catch (const json::exception& error) {
    throw InputError(fmt::format("{}: not valid JSON ({})", path, error.what()));
  }
  return manifest_from_json(path, document);
}

void write_locomotive_manifest(const std::filesystem::path& path,
                               const std::vector<ManifestChannel>& channels,
                               const std::string& generated_by) {
  // One channel per line: the file is read by people as much as by programs.
  std::string text =
      fmt::format("{{\n  \"generated_by\": {},\n  \"channels\": [\n", json(generated_by).dump());
  for (std::size_t k = 0; k < channels.size(); ++k) {
    const ManifestChannel& c = channels[k];
    nlohmann::ordered_json entry{{"channel", c.channel},
                                 {"axle", c.axle},
                                 {"side", manifest_side_name(c.side)},
                                 {"file", c.file}};
    if (!c.calibration.empty()) entry["calibration"] = c.calibration;
    text += "    " + entry.dump() + (k + 1 < channels.size() ? ",\n" : "\n");
  }
  text += "  ]\n}\n";
  std::ofstream file(path, std::ios::binary);
  file << text;
  file.close();
  if (!file) throw std::runtime_error("cannot write " + path.string());
}

}  // namespace flange::host
