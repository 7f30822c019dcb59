// SPDX-License-Identifier: MIT
#include "design_command.h"

#include <fmt/format.h>

#include <cmath>
#include <ostream>
#include <stdexcept>

#include "channel_sets.h"
#include "cli.h"
#include "design_error.h"
#include "design_outputs.h"
#include "version.h"

namespace flange::cli {

// What the command takes from the generator (coeffs/).
using coeffs::BadArgument;
using coeffs::DesignRecord;
using coeffs::DesignRejected;
using coeffs::DesignRequest;
using coeffs::Structure;

CLI::App* add_design_command(CLI::App& app, DesignOptions& options) {
  CLI::App* cmd = app.add_subcommand(
      "design",
      "Design a Butterworth low-pass, quantise it for the FPGA and write its coefficient set");
  DesignRequest& r = options.request;
  cmd->add_option("--fs", r.fs_hz, "sample rate in Hz (> 0)")->required();
  cmd->add_option("--fp", r.fp_hz, "passband edge in Hz (0 < fp < fa)");
  cmd->add_option("--fa", r.fa_hz, "stopband edge in Hz (fp < fa < fs/2)");
  cmd->add_option("--ap", r.ap_db, "maximum passband loss in dB (0 < ap < aa)");
  cmd->add_option("--aa", r.aa_db, "minimum stopband attenuation in dB (> ap)");
  cmd->add_option("--order", r.order, "filter order (1 to 32), with --fc");
  cmd->add_option("--fc", r.fc_hz, "3 dB cut-off in Hz (0 < fc < fs/2), with --order");
  cmd->add_option("--tf-b", r.tf_b, "given numerator b0,b1,... (analyse and quantise it)")
      ->delimiter(',');
  cmd->add_option("--tf-a", r.tf_a, "given denominator a0,a1,...")->delimiter(',');
  cmd->add_option("--structure", options.structure,
                  "df1: one direct-form-I section of order N; sos: cascade of biquads")
      ->check(CLI::IsMember({"df1", "sos"}))
      ->default_str("sos");
  cmd->add_option("--coef-bits", r.widths.coef_bits, "coefficient width (4 to 32)")
      ->default_val(18);
  cmd->add_option("--data-bits", r.widths.data_bits, "sample width (4 to 24)")->default_val(16);
  cmd->add_option("--acc-bits", r.widths.acc_bits, "accumulator width (16 to 64)")->default_val(48);
  cmd->add_option("--channels", options.channels,
                  fmt::format("channels sharing the core and this set (1 to {})", coeffs::kMaxChannels))
      ->default_val(1);
  cmd->add_option("--channel-fc", options.channel_fc_hz,
                  "a coefficient set per channel: channel c's cut-off in Hz, with --order "
                  "(the channel count is the list's length)")
      ->delimiter(',');
  cmd->add_option("--name", r.name, "name of the filter in reports")->default_val("iir");
  cmd->add_option("--spec-tolerance-db", r.limits.spec_tolerance_db,
                  "slack on ap and aa after rounding (>= 0)")
      ->default_val(0.01);
  cmd->add_option("--max-dc-error-db", r.limits.max_dc_error_db,
                  "DC gain error allowed without a spec (> 0)")
      ->default_val(0.1);
  cmd->add_option("--max-passband-deviation-db", r.limits.max_passband_deviation_db,
                  "largest |quantised - float| response below fc without a spec (> 0)")
      ->default_val(0.5);
  cmd->add_option("--out", options.out_dir,
                  "folder for filter.json, coeffs.mem, "
                  "iir_coeffs_pkg.sv and response.svg");
  cmd->add_flag("--no-plot", options.no_plot, "skip the frequency-response plot");
  return cmd;
}

std::string command_without_out(const std::vector<std::string>& command_line) {
  std::string text = "flange";
  for (std::size_t i = 0; i < command_line.size(); ++i) {
    const std::string& word = command_line[i];
    if (word == "--out") {
      ++i;
      continue;
    }
    if (word.rfind("--out=", 0) == 0) continue;
    text += " " + word;
  }
  return text;
}

namespace {

// One set for every channel, or (--channel-fc) a set per channel.
DesignRecord design_record(const DesignOptions& options, const DesignRequest& request,
                           const std::string& generated_by) {
  if (options.channel_fc_hz.empty()) {
    DesignRecord record = generate_design(request, generated_by);
    record.channels = options.channels;
    return record;
  }
  if (request.fc_hz || request.fp_hz || !request.tf_b.empty()) {
    throw BadArgument("--channel-fc: gives every channel's cut-off; leave out --fc, the spec and "
                      "--tf-b/--tf-a");
  }
  if (options.channels != 1 &&
      options.channels != static_cast<int>(options.channel_fc_hz.size())) {
    throw BadArgument(fmt::format("--channels {} but --channel-fc names {} cut-offs",
                                  options.channels, options.channel_fc_hz.size()));
  }
  return generate_channel_designs(request, options.channel_fc_hz, generated_by);
}

}  // namespace

int run_design_command(const DesignOptions& options, const std::vector<std::string>& command_line,
                       std::ostream& out) {
  DesignRequest request = options.request;
  request.structure = options.structure == "df1" ? Structure::kDf1 : Structure::kSos;
  if (!std::isfinite(request.limits.spec_tolerance_db) || request.limits.spec_tolerance_db < 0) {
    throw BadArgument("--spec-tolerance-db: must be a finite number >= 0");
  }
  if (!std::isfinite(request.limits.max_passband_deviation_db) ||
      request.limits.max_passband_deviation_db <= 0) {
    throw BadArgument("--max-passband-deviation-db: must be a finite number > 0");
  }
  if (!std::isfinite(request.limits.max_dc_error_db) || request.limits.max_dc_error_db <= 0) {
    throw BadArgument("--max-dc-error-db: must be a finite number > 0");
  }
  if (options.channels < 1 || options.channels > coeffs::kMaxChannels) {
    throw BadArgument(
        fmt::format("--channels: {} is outside 1 to {}", options.channels, coeffs::kMaxChannels));
  }
  DesignRecord record =
      design_record(options, request, runtime::generated_by(command_without_out(command_line)));
  out << design_report(record);
  if (!record.analysis.rejection.empty()) throw DesignRejected(record.analysis.rejection);
  if (options.out_dir) {
    write_design(record, *options.out_dir, !options.no_plot);
    out << "  wrote " << options.out_dir->string() << "/{" << coeffs::kFilterJsonFile << ", "
        << coeffs::kRomImageFile << ", " << coeffs::kPackageFile << (options.no_plot ? "" : ", ")
        << (options.no_plot ? "" : coeffs::kPlotFile) << "}\n";
  }
  return kExitOk;
}

}  // namespace flange::cli
