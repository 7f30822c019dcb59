// SPDX-License-Identifier: MIT
#include "improved_twin_reasons.h"

#include <fmt/format.h>

#include "verdict_reasons.h"

namespace flange::diagnose::reasons {
namespace {

// What a twin holding lines of each session does with them.
std::string played_from_each_session() {
  return " for `flange simulate` to play; a diagnosis against this twin fits each session's own "
         "lines at the mains' aliases and takes them out, since their phase (and with a wandering "
         "grid their amplitude) is each session's own";
}

}  // namespace

const char* held_as_text(HeldAs held) {
  switch (held) {
    case HeldAs::kLibraryEffect:
      return "library effect";
    case HeldAs::kLibraryEffectAndTable:
      return "library effect and table";
    case HeldAs::kTable:
      return "table";
    case HeldAs::kConverter:
      return "converter";
    case HeldAs::kWhiteNoise:
      return "white noise";
    case HeldAs::kMountMotion:
      return "mount motion";
    case HeldAs::kSessionLines:
      return "session's own lines";
    case HeldAs::kNotHeld:
      break;
  }
  return "not held";
}

std::string held_in_white_noise(double lsb_v) {
  return fmt::format(
      "its codes are not reproduced by the converter on this grid, so the twin holds its rounding "
      "in the white noise level, and names the grid (noise.rounding_lsb_v = {:.4g} V) so that a "
      "diagnosis against it does not name the converter again",
      lsb_v);
}

std::string held_as_converter(bool with_daq_gain) {
  std::string note = "the converter on the recorded grid, with its code boundaries";
  if (with_daq_gain) {
    note += "; the DAQ gain calibration it showed is in the table (the twin has no gain effect)";
  }
  return note;
}

std::string held_as_mount_motion(double rms_mm) {
  return fmt::format(
      "vibration at the recognised {:.3g} mm RMS over the effect's default band (the signature "
      "gives its size, not its band or phases)",
      rms_mm);
}

std::string held_as_one_session_line(double rms_v, double mains_hz) {
  return fmt::format("one line of the lines' {:.3g} V RMS at the {:g} Hz mains", rms_v,
                     mains_hz) +
         played_from_each_session();
}

std::string held_as_session_lines_effect() {
  return held_as_library_effect() + played_from_each_session();
}

std::string not_held_in_table(double misfit_v, double allowed_v) {
  return fmt::format(
      "its free shape follows more than clearance, temperature and age: the table reproduces it "
      "only to {:.2g} V RMS, above the {:.2g} V the noise allows; the twin holds that "
      "approximation",
      misfit_v, allowed_v);
}

std::string held_as_member_and_table(double misfit_v) {
  return fmt::format(
      "its free shape's summary as the library effect (a lag's mean delay or its mix in volts, a "
      "skew's law), and "
      "what that leaves of the shape, with the other free shapes, in the tabulated effect "
      "(reproduced to {:.2g} V RMS on the worse part)",
      misfit_v);
}

std::string held_in_table(double misfit_v) {
  return fmt::format(
      "its free shape, with the other free shapes, as the tabulated effect (reproduced to {:.2g} "
      "V RMS on the worse part)",
      misfit_v);
}

std::string held_as_library_effect() { return "the library effect with its fitted parameters"; }

std::string improved_twin_summary(std::size_t findings, Status status, double noise_v) {
  return findings > 0
             ? fmt::format(
                   "the twin given, with the {} findings of the \"{}\" verdict and the white "
                   "noise at {:.4g} V",
                   findings, status_text(status), noise_v)
             : fmt::format(
                   "the twin given, with the white noise at {:.4g} V; the \"{}\" verdict selects "
                   "no effect to add",
                   noise_v, status_text(status));
}

std::string not_held_note(const std::string& name, const std::string& why) {
  return name + " not held: " + why;
}

}  // namespace flange::diagnose::reasons
