// SPDX-License-Identifier: MIT
// The double-precision filter that the fixed-point core approximates: the float design of the
// same filter.json, for fidelity measurements (SNR, error) against the bit-accurate model.
//
// Every stage is a direct form I, y[n] = sum b[i] x[n-i] - sum a[j] y[n-j], summed in that order
// (b[0] first, a[M] last) in double. process() is step() over a block: the same kernel with the
// same operations in the same order, so both give the same outputs bit for bit (in a build
// without floating-point contraction; reference_filter_test allows 1e-13 of full scale for one
// that contracts); for biquads and first-order stages with up to 8 stages it keeps the words
// and the history in registers with the stages unrolled, so the processor overlaps one sample's
// later stages with the next sample's earlier ones (docs/benchmarks_core.md, "Sample model").
#pragma once

#include <complex>
#include <cstddef>
#include <span>
#include <utility>
#include <vector>

#include "filter_json.h"

namespace flange::model {

class ReferenceFilter {
 public:
  enum class Form {
    kSos,    // the float second-order sections, cascaded (what the sos hardware approximates)
    kDirect  // the whole b/a transfer function in one direct form I (poorly conditioned for
             // narrow high-order filters: use it to show why, not as the yardstick)
  };

  // The leftover gain of the design is applied to every output, as the host does.
  explicit ReferenceFilter(const FloatDesign& design, Form form = Form::kSos);

  // The core's own cascade in double: the ROM words of `config` as coefficients (b = B 2^-Fb,
  // a = -A 2^-Fa, docs/fixed_point.md), then `leftover_gain` (the design's). Against the
  // bit-accurate model it measures only the core's arithmetic; against the float design, only the
  // rounding of the coefficients. `config` must be valid (validate_core_config).
  static ReferenceFilter quantized(const CoreConfig& config, double leftover_gain);

  // The frequency response at `f_over_fs` (f / fs, 0 to 0.5), leftover gain included.
  std::complex<double> response(double f_over_fs) const;

  // One input in full-scale units (the core's sample / 2^(D-1)); returns the output in the same
  // units.
  double step(double x);
  // in.size() inputs in order, continuing from the previous call (or step()); out[i] is what
  // step(in[i]) would return. out.size() must equal in.size() (std::invalid_argument); in and out
  // may be the same span.
  void process(std::span<const double> in, std::span<double> out);
  void reset();

 private:
  // Per stage b and a (a[0] = 1), of any lengths.
  using BA = std::pair<std::vector<std::vector<double>>, std::vector<std::vector<double>>>;
  static BA stages_of(const FloatDesign& design, Form form);
  ReferenceFilter(BA stages, double gain);
  template <int kOrder, int kStages>
  void run(const double* in, double* out, std::size_t n);

  double gain_;
  int stages_ = 0;  // one for kDirect
  int order_ = 0;   // M: every stage's b and a padded with zeros to M + 1 terms
  // Per stage b[0..M] then a[1..M], normalised so that a[0] = 1: 2M + 1 words.
  std::vector<double> coef_;
  // Line l (0..stages_: the input, then each stage's output, which is the next stage's input)
  // holds its values of ages 1..M at [l M, l M + M).
  std::vector<double> history_;
  using BlockRun = void (ReferenceFilter::*)(const double*, double*, std::size_t);
  BlockRun block_run_ = nullptr;
};

}  // namespace flange::model
