// SPDX-License-Identifier: MIT
// The locomotive manifest loader on any bytes: channels that name existing files, or InputError.
// The corpus's manifests name flange_fuzz_manifest_channel.csv, which the harness keeps in the
// temporary folder beside the input, so that inputs get past the file checks.
#include <cstdint>
#include <filesystem>
#include <fstream>

#include "fuzz_input_file.h"
#include "input_error.h"
#include "locomotive_manifest.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const bool channel_file_written = [] {
    std::ofstream(std::filesystem::temp_directory_path() / "flange_fuzz_manifest_channel.csv")
        << "t_s,clearance_mm,temp_c,voltage_v\n0,2,20,1\n";
    return true;
  }();
  (void)channel_file_written;
  const auto path = flange::fuzz::write_fuzz_input(data, size, ".json");
  try {
    const flange::host::LocomotiveManifest manifest =
        flange::host::load_locomotive_manifest(path.string());
    for (const flange::host::ManifestChannel& channel : manifest.channels) {
      if (channel.channel < 0 || channel.channel > 11 || channel.axle < 1 || channel.axle > 6) {
        __builtin_trap();  // the loader let a value out of its range through
      }
    }
  } catch (const flange::host::InputError&) {
  }
  return 0;
}
