// SPDX-License-Identifier: MIT
#include "hw_diagnose_command.h"

#include <ostream>
#include <stdexcept>

#include "cli.h"
#include "hw_diagnosis.h"
#include "input_error.h"

namespace flange::cli {

void add_hw_diagnose_options(CLI::App& diagnose, HwDiagnoseOptions& options) {
  diagnose::HwRequest& o = options.request;
  diagnose.add_flag("--hw", options.hw,
                    "hardware layer: the gap between the float design and the Verilated RTL, "
                    "attributed to the fixed-point effects one at a time");
  diagnose.add_option("--coeffs", o.coeffs,
                      "--hw: filter.json of a coefficient set (iir_coeffs_pkg.sv and coeffs.mem "
                      "beside it)");
  diagnose
      .add_option("--stimulus", o.stimulus,
                  "--hw: random (half scale), fullscale, sweep (log sine sweep fc/20 .. 0.49 "
                  "fs), step, impulse, or FILE.csv (one sample in LSB per line, fractions "
                  "allowed)")
      ->default_val("random");
  diagnose.add_option("--samples", o.samples, "--hw: number of samples, 1..10^7")
      ->default_val(10000);
  diagnose.add_flag("--thesis-eq-4-20", o.thesis_eq_4_20,
                    "--hw: the thesis's printed eq. 4.20 coefficients as the real, against the "
                    "float design of --coeffs (coeffs/vehicle_sos/filter.json)");
  diagnose.add_option("--tf-b", o.tf_b, "--hw: printed numerator b0,b1,... as the real")
      ->delimiter(',');
  diagnose.add_option("--tf-a", o.tf_a, "--hw: printed denominator a0,a1,... as the real")
      ->delimiter(',');
}

void add_hw_diagnose_shared_options(CLI::App& diagnose, HwDiagnoseOptions& options) {
  diagnose.add_option("--seed", options.request.seed, "seed of the random stimuli")->default_val(1);
  diagnose.add_option("--out", options.out,
                      "folder for hw_diagnosis.json, hw_diagnosis.html, SVGs");
}

int run_hw_diagnosis(const HwDiagnoseOptions& options, std::ostream& out, std::ostream& err) {
  const diagnose::HwRequest& request = options.request;
  const diagnose::HwInputs in = diagnose::load_hw_inputs(request);
  diagnose::HwDiagnosis d = request.printed() ? diagnose::diagnose_printed(request, in)
                                              : diagnose::diagnose_rtl(request, in, err);
  d.coeffs = request.coeffs.string();
  d.stimulus = request.stimulus;
  d.seed = request.seed;
  d.sample_width = in.config.sample_width;
  d.requested_samples = request.samples;
  diagnose::print_hw_diagnosis(d, out);
  if (options.out) diagnose::write_hw_diagnosis(d, *options.out);
  if (request.printed()) return kExitOk;
  return d.explained() ? kExitOk : kExitFailure;
}

}  // namespace flange::cli
