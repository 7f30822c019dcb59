// SPDX-License-Identifier: MIT
#include "generator.h"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "design_error.h"

namespace flange::coeffs {

namespace {

std::string num(double value) { return fmt::format("{:.6g}", value); }

void require_positive_finite(const char* argument, double value) {
  if (!std::isfinite(value) || value <= 0.0) {
    throw BadArgument(fmt::format("{} {}: must be a finite number > 0", argument, num(value)));
  }
}

void require_range(const char* argument, int value, int lo, int hi) {
  if (value < lo || value > hi) {
    throw BadArgument(fmt::format("{} {}: valid range is {} to {}", argument, value, lo, hi));
  }
}

std::optional<LowpassSpec> validated_spec(const DesignRequest& request) {
  const int given = request.fp_hz.has_value() + request.fa_hz.has_value() +
                    request.ap_db.has_value() + request.aa_db.has_value();
  if (given == 0) return std::nullopt;
  if (given != 4) {
    throw BadArgument("--fp --fa --ap --aa: give all four of the spec, or none");
  }
  LowpassSpec spec{request.fs_hz, *request.fp_hz, *request.fa_hz, *request.ap_db, *request.aa_db};
  require_positive_finite("--fp", spec.fp_hz);
  require_positive_finite("--fa", spec.fa_hz);
  require_positive_finite("--ap", spec.ap_db);
  require_positive_finite("--aa", spec.aa_db);
  const double nyquist = spec.fs_hz / 2.0;
  if (spec.fa_hz >= nyquist) {
    throw BadArgument(fmt::format(
        "--fa {}: must be below the Nyquist frequency fs/2 = {} Hz (valid: fp < fa < fs/2)",
        num(spec.fa_hz), num(nyquist)));
  }
  if (spec.fp_hz >= spec.fa_hz) {
    throw BadArgument(fmt::format("--fp {}: must be below --fa {} (valid: 0 < fp < fa < fs/2)",
                                  num(spec.fp_hz), num(spec.fa_hz)));
  }
  if (spec.ap_db >= spec.aa_db) {
    throw BadArgument(fmt::format("--ap {}: must be below --aa {} (valid: 0 < ap < aa)",
                                  num(spec.ap_db), num(spec.aa_db)));
  }
  return spec;
}

void validate_widths(const HardwareWidths& widths) {
  require_range("--coef-bits", widths.coef_bits, kMinCoefBits, kMaxCoefBits);
  require_range("--data-bits", widths.data_bits, kMinDataBits, kMaxDataBits);
  require_range("--acc-bits", widths.acc_bits, kMinAccBits, kMaxAccBits);
}

// The -3 dB frequency of a given stable low-pass response, by bisection below Nyquist.
double cutoff_of(const FloatDesign& design) {
  const double dc = std::abs(float_response(design, 0.0));
  const double target = dc / std::sqrt(2.0);
  double lo = 0.0;
  double hi = std::numbers::pi;
  if (std::abs(float_response(design, hi)) >= target) return design.fs_hz / 2.0;
  for (int i = 0; i < 200; ++i) {
    const double mid = (lo + hi) / 2.0;
    (std::abs(float_response(design, mid)) > target ? lo : hi) = mid;
  }
  return lo * design.fs_hz / (2.0 * std::numbers::pi);
}

// A float design from given b/a coefficients: its roots, gain and cascade.
FloatDesign design_from_transfer_function(const DesignRequest& request,
                                          std::optional<LowpassSpec> spec) {
  const std::size_t max_len = static_cast<std::size_t>(kMaxOrder) + 1;
  for (const auto* list : {&request.tf_b, &request.tf_a}) {
    const char* argument = list == &request.tf_b ? "--tf-b" : "--tf-a";
    if (list->size() < 2 || list->size() > max_len) {
      throw BadArgument(fmt::format("{}: {} coefficients given; valid is 2 to {}", argument,
                                    list->size(), max_len));
    }
    for (double value : *list) {
      if (!std::isfinite(value)) {
        throw BadArgument(fmt::format("{}: every coefficient must be finite", argument));
      }
    }
  }
  if (request.tf_a.front() == 0.0) throw BadArgument("--tf-a: a[0] must not be zero");
  FloatDesign design;
  design.fs_hz = request.fs_hz;
  design.spec = spec;
  const double a0 = request.tf_a.front();
  design.order = static_cast<int>(std::max(request.tf_b.size(), request.tf_a.size())) - 1;
  for (double value : request.tf_b) design.b.push_back(value / a0);
  for (double value : request.tf_a) design.a.push_back(value / a0);
  design.b.resize(static_cast<std::size_t>(design.order) + 1, 0.0);
  design.a.resize(static_cast<std::size_t>(design.order) + 1, 0.0);
  std::size_t lead = 0;
  while (lead < design.b.size() && design.b[lead] == 0.0) ++lead;
  if (lead == design.b.size()) throw BadArgument("--tf-b: all coefficients are zero");
  // Roots in z of a polynomial in z^-1 with trailing zeros trimmed; the trimmed ones are roots
  // at the origin.
  auto roots_in_z = [](std::vector<double> coefficients) {
    std::size_t at_origin = 0;
    while (coefficients.size() > 1 && coefficients.back() == 0.0) {
      coefficients.pop_back();
      ++at_origin;
    }
    std::vector<Complex> roots = polynomial_roots(coefficients);
    roots.insert(roots.end(), at_origin, Complex(0.0, 0.0));
    return roots;
  };
  design.zpk.zeros = roots_in_z(
      std::vector<double>(design.b.begin() + static_cast<std::ptrdiff_t>(lead), design.b.end()));
  design.zpk.poles = roots_in_z(design.a);
  design.zpk.gain = design.b[lead];
  double radius = 0.0;
  int outside = 0;
  for (const Complex& pole : design.zpk.poles) {
    radius = std::max(radius, std::abs(pole));
    if (std::abs(pole) >= 1.0) ++outside;
  }
  if (outside > 0) {
    throw DesignRejected(fmt::format(
        "the given coefficients are unstable before any quantisation: {} pole{} on or outside "
        "the unit circle (max |z| = {:.4f}); design from the spec or from --order --fc instead",
        outside, outside == 1 ? "" : "s", radius));
  }
  design.fc_hz = cutoff_of(design);
  design.cascade = scale_cascade_linf(pair_sections_nearest(design.zpk), design.zpk.gain);
  return design;
}

// A cut-off that is a tiny fraction of the sample rate puts the poles so close to z = 1 that
// double precision cannot hold the design; say so instead of quantising rounding noise.
void require_representable(const FloatDesign& design) {
  bool finite = std::isfinite(design.cascade.leftover_gain);
  for (const Section& section : design.cascade.sections) {
    for (double value : section.b) finite = finite && std::isfinite(value);
    for (double value : section.a) finite = finite && std::isfinite(value);
  }
  double radius = 0.0;
  for (const Complex& pole : design.zpk.poles) radius = std::max(radius, std::abs(pole));
  if (!finite || radius >= 1.0 - 1e-12) {
    throw DesignRejected(fmt::format(
        "fc / fs = {:.3g} is too small for a stable design in double precision (poles within "
        "{:.1g} of z = 1); raise fc or lower fs (decimate before filtering)",
        design.fc_hz / design.fs_hz, std::max(0.0, 1.0 - radius)));
  }
}

}  // namespace

DesignRecord generate_design(const DesignRequest& request, const std::string& generated_by) {
  require_positive_finite("--fs", request.fs_hz);
  validate_widths(request.widths);
  const std::optional<LowpassSpec> spec = validated_spec(request);
  const bool explicit_design = request.order.has_value() || request.fc_hz.has_value();
  const bool given_tf = !request.tf_b.empty() || !request.tf_a.empty();
  if (explicit_design && given_tf) {
    throw BadArgument("--order/--fc and --tf-b/--tf-a: choose one way to give the filter");
  }

  DesignRecord record;
  record.name = request.name;
  record.generated_by = generated_by;
  if (given_tf) {
    if (request.tf_b.empty() || request.tf_a.empty()) {
      throw BadArgument("--tf-b --tf-a: give both the numerator and the denominator");
    }
    record.design = design_from_transfer_function(request, spec);
  } else if (explicit_design) {
    if (!request.order || !request.fc_hz) {
      throw BadArgument("--order --fc: give both the order and the 3 dB cut-off");
    }
    require_range("--order", *request.order, kMinOrder, kMaxOrder);
    require_positive_finite("--fc", *request.fc_hz);
    if (*request.fc_hz >= request.fs_hz / 2.0) {
      throw BadArgument(fmt::format(
          "--fc {}: must be below the Nyquist frequency fs/2 = {} Hz (valid: 0 < fc < fs/2)",
          num(*request.fc_hz), num(request.fs_hz / 2.0)));
    }
    record.design = design_butterworth(*request.order, *request.fc_hz, request.fs_hz, spec);
  } else {
    if (!spec) {
      throw BadArgument(
          "design: give a spec (--fp --fa --ap --aa), an order and cut-off (--order --fc), or "
          "coefficients (--tf-b --tf-a), each with --fs");
    }
    const int order = butterworth_min_order(*spec);
    if (order > kMaxOrder) {
      throw BadArgument(fmt::format(
          "--fp --fa --ap --aa: this spec needs a Butterworth order of {}; valid orders are {} "
          "to {} (widen fa - fp or relax ap/aa)",
          order, kMinOrder, kMaxOrder));
    }
    record.design = design_butterworth(std::max(order, kMinOrder),
                                       butterworth_cutoff_hz(*spec, std::max(order, kMinOrder)),
                                       request.fs_hz, spec);
  }
  require_representable(record.design);
  record.quantized =
      quantize(record.design, request.structure, request.widths, request.max_feedback_shift,
               request.max_coef_frac_bits);
  record.analysis = analyse(record.design, record.quantized, request.limits);
  return record;
}

}  // namespace flange::coeffs
