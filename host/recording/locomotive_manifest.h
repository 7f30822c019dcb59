// SPDX-License-Identifier: MIT
// The multichannel recording of a locomotive: one recording CSV per sensor channel, in the usual
// format (so every single-channel tool reads each file), and a manifest, locomotive.json, that
// says which wheel each channel measures and where its file is (docs/locomotive.md):
//
//   {"generated_by": "...",
//    "channels": [{"channel": 0, "axle": 1, "side": "left", "file": "channel_00.csv",
//                  "calibration": "cal/wheel_1l.json"}, ...]}
//
// "calibration" is optional: the wheel's own sensor calibration.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace flange::host {

inline constexpr int kManifestMaxChannels = 12;  // channels 0 to 11
inline constexpr int kManifestAxles = 6;         // axles 1 (leading) to 6

enum class ManifestSide { kLeft, kRight };

struct ManifestChannel {
  int channel = 0;  // 0 to 11, each once
  int axle = 1;     // 1 to 6; with side, each wheel once
  ManifestSide side = ManifestSide::kLeft;
  std::string file;            // as written: relative to the manifest's folder
  std::filesystem::path path;  // the file as found: the manifest's folder / file
  // This wheel's sensor calibration (model.json from flange calibrate), optional: as written
  // (relative to the manifest's folder) and as found; empty: the command's --calibration.
  std::string calibration;
  std::filesystem::path calibration_path;
};

struct LocomotiveManifest {
  std::string path;                       // the manifest file itself
  std::vector<ManifestChannel> channels;  // 1 to 12, sorted by channel
};

// "left" or "right".
const char* manifest_side_name(ManifestSide side);

// "axle 1 left".
std::string wheel_label(const ManifestChannel& channel);

// The name the locomotive's files take in their folder: channel_00.csv to channel_11.csv.
std::string channel_file_name(int channel);

// Reads and checks a manifest. Throws InputError with one line naming the file, the field
// (e.g. channels[3].axle) and its valid range: file missing or unreadable, not valid JSON, no
// channels array, a channel out of 0..11 or listed twice, an axle out of 1..6, a side other than
// left/right, a wheel or file listed twice, a channel's file or calibration missing. Keys it does not know are
// ignored with a note (input_notes.h).
LocomotiveManifest load_locomotive_manifest(const std::string& path);

// Writes a manifest listing `channels` (their channel, axle, side and file); `generated_by` is
// the command that made it. Throws std::runtime_error when the file cannot be written.
void write_locomotive_manifest(const std::filesystem::path& path,
                               const std::vector<ManifestChannel>& channels,
                               const std::string& generated_by);

}  // namespace flange::host
