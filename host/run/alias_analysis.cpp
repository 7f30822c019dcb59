// SPDX-License-Identifier: MIT
#include "alias_analysis.h"

#include <fmt/format.h>

#include <cmath>
#include <complex>
#include <fstream>
#include <numbers>
#include <sstream>
#include <unsupported/Eigen/FFT>
#include <vector>

#include "filter_json.h"
#include "input_error.h"
#include "recording_csv.h"
#include "welch_spectrum.h"

namespace flange::host {

namespace {

// t_s and clearance_filt_mm of a flange run output CSV.
void read_run_output(const std::string& path, std::vector<double>& t,
                     std::vector<double>& filtered) {
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot open the run output");
  std::string line;
  std::getline(in, line);
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    std::string t_text, raw_text, filt_text;
    std::getline(fields, t_text, ',');
    std::getline(fields, raw_text, ',');
    std::getline(fields, filt_text, ',');
    const std::optional<double> time = parse_number(t_text);
    const std::optional<double> value = parse_number(filt_text);
    if (!time || !value) throw InputError(fmt::format("{}: malformed row '{}'", path, line));
    t.push_back(*time);
    filtered.push_back(*value);
  }
}

double gain_db(const model::FloatDesign& design, double f_hz) {
  const std::complex<double> w = std::polar(1.0, -2.0 * std::numbers::pi * f_hz / design.fs_hz);
  std::complex<double> h(design.leftover_gain, 0.0);
  for (const auto& row : design.sos) {
    h *= (row[0] + w * (row[1] + w * row[2])) / (row[3] + w * (row[4] + w * row[5]));
  }
  return 20.0 * std::log10(std::abs(h));
}

}  // namespace

AliasAnalysis analyse_aliasing(const AliasAnalysisInput& input) {
  std::vector<double> truth;
  double fast_fs = 0.0;
  {
    RecordingReader reader(input.fast_recording);
    std::optional<double> first_t;
    while (const std::optional<RecordingRow> row = reader.next()) {
      if (!row->clearance_mm) {
        throw InputError(
            fmt::format("{}:{}: no clearance_mm truth", input.fast_recording, row->line));
      }
      if (first_t && fast_fs == 0.0) fast_fs = 1.0 / (row->t_s - *first_t);
      if (!first_t) first_t = row->t_s;
      truth.push_back(*row->clearance_mm);
    }
  }
  if (truth.size() < 4096) throw InputError(input.fast_recording + ": too short for a spectrum");
  const model::FloatDesign slow_design = model::load_float_design(input.slow_coeffs);
  const model::FloatDesign fast_design = model::load_float_design(input.fast_coeffs);

  AliasAnalysis result;
  // The mode: the truth's spectral peak in 3-10 Hz.
  WelchSpectrum spectrum(1024, fast_fs);
  for (double d : truth) spectrum.push(d);
  const std::vector<double> psd = spectrum.psd();
  const std::vector<double> f = spectrum.frequencies_hz();
  double best = -1.0;
  for (std::size_t k = 0; k < psd.size(); ++k) {
    if (f[k] >= 3.0 && f[k] <= 10.0 && psd[k] > best) {
      best = psd[k];
      result.mode_hz = f[k];
    }
  }
  const double slow_fs = slow_design.fs_hz;
  result.alias_hz = std::abs(result.mode_hz - slow_fs * std::round(result.mode_hz / slow_fs));
  result.slow_gain_at_alias_db = gain_db(slow_design, result.alias_hz);
  result.fast_gain_at_mode_db = gain_db(fast_design, result.mode_hz);

  // The slow truth: the fast truth through a zero-phase brick wall at truth_band_hz.
  Eigen::FFT<double> fft;
  std::vector<std::complex<double>> bins;
  fft.fwd(bins, truth);
  const std::size_t n = truth.size();
  for (std::size_t k = 0; k < n; ++k) {
    const double freq = fast_fs * static_cast<double>(std::min(k, n - k)) / static_cast<double>(n);
    if (freq > input.truth_band_hz) bins[k] = 0.0;
  }
  std::vector<double> slow_truth;
  fft.inv(slow_truth, bins);

  // Each chain against the slow truth at its own group delay.
  auto rms_against_truth = [&](const std::vector<double>& t, const std::vector<double>& y,
                               double delay_s, int stride) {
    double sum = 0.0;
    std::size_t count = 0;
    for (std::size_t k = 0; k < t.size(); k += static_cast<std::size_t>(stride)) {
      if (t[k] < input.skip_s) continue;
      const long index = std::lround((t[k] - delay_s) * fast_fs);
      if (index < 0 || static_cast<std::size_t>(index) >= slow_truth.size()) continue;
      const double e = y[k] - slow_truth[static_cast<std::size_t>(index)];
      sum += e * e;
      ++count;
    }
    return count ? std::sqrt(sum / static_cast<double>(count)) : 0.0;
  };
  std::vector<double> t_slow, y_slow, t_fast, y_fast;
  read_run_output(input.slow_output, t_slow, y_slow);
  read_run_output(input.fast_output, t_fast, y_fast);
  result.slow_rms_mm = rms_against_truth(
      t_slow, y_slow, model::dc_group_delay_samples(slow_design) / slow_design.fs_hz, 1);
  result.fast_rms_mm = rms_against_truth(
      t_fast, y_fast, model::dc_group_delay_samples(fast_design) / fast_design.fs_hz,
      input.decimation);
  return result;
}

}  // namespace flange::host
