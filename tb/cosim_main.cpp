// SPDX-License-Identifier: MIT
// The co-simulation runner that `flange cosim` builds once per coefficient set (the RTL package
// differs per set) and then runs; its options are those of `flange cosim`, plus --stream for
// `flange run --engine rtl`.
#include <CLI/CLI.hpp>
#include <exception>
#include <iostream>
#include <memory>

#include "cosim_run.h"
#include "iir_core_dut.h"
#include "stream_run.h"

int main(int argc, char** argv) {
  flange::tb::CosimOptions options;
  CLI::App app{"flange cosim runner: Verilated iir_core against the bit-accurate model"};
  app.add_option("--coeffs", options.coeffs, "filter.json of the set")->required();
  app.add_option("--samples", options.samples, "number of samples (>= 1)");
  app.add_option("--seed", options.seed, "seed of the random stimuli");
  app.add_option("--stimulus", options.stimulus, "random|fullscale|sweep|step|impulse|FILE.csv");
  app.add_option("--trace", options.trace, "FST waveform file");
  bool stream = false;
  app.add_flag("--stream", stream,
               "serve sample blocks on stdin/stdout for flange run --engine rtl (tb/stream_run.h)");
  int channel = 0;
  app.add_option("--channel", channel, "with --stream: the channel every sample is strobed on");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  try {
    if (stream) {
      const std::unique_ptr<flange::tb::Dut> dut = flange::tb::make_dut();
      return flange::tb::serve_stream(options.coeffs, *dut, stdin, stdout, channel);
    }
    return flange::tb::run_cosim(
        options, [](const std::filesystem::path& fst) { return flange::tb::make_dut(fst); },
        std::cout, std::cerr);
  } catch (const std::exception& e) {
    std::cerr << "flange cosim: " << e.what() << "\n";
    return 2;
  }
}
