// SPDX-License-Identifier: MIT
// The blind check of the diagnosis on a reality given as a parameter (docs/diagnose.md, "Blind
// check"): the twin's (diagnose_selftest.h) or the alternative one (diagnose/alt_check/). A
// reality draws a case (its truth), makes the case's two sessions and says what its truth is in
// the harness's terms; the harness diagnoses the sessions blind (as `flange diagnose --real A
// --holdout B` reads them), scores the diagnosis against the truth and counts the scores. The
// report of a run (tables, selftest.json) is blind_report.h.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "diagnosis.h"
#include "parallel_work.h"
#include "recording_series.h"

namespace flange::diagnose {

// The kinds of case both realities draw: one or two library effects, none, or one outside the
// library.
enum class BlindKind { kSingle, kPair, kNull, kOutside };
bool in_library(BlindKind kind);

// What the harness knows of a case's truth: enough to score a diagnosis of it.
struct BlindTruth {
  BlindKind kind = BlindKind::kNull;
  std::vector<std::string> classes;  // the true effects, by the name a claim gives them
  bool bias_type = false;            // every true effect is a bias the twin could subtract (not
                                     // vibration, ADC quantisation)
  double noise_std_v = 0.0;          // the true white noise, V (the excess shrink is above it)
};

struct BlindScore {
  std::vector<std::string> claimed;  // the effects an "explained" or "partly explained" verdict
                                     // names, in its order
  std::vector<bool> claim_right;     // for each claim, whether its effect is in the truth
  std::string nearest;               // "unexplained": the effect it came nearest to ("" if none)
  double nearest_shrink_pct = 0.0;   // how far that effect alone shrank the held-out gap
  bool verdict_correct = false;      // in-library: explained; null: none; outside: unexplained
  bool top_correct = false;          // in-library: the first effect named is a true one
  bool all_found = false;            // in-library: every true effect is named
  // The same two where a finding stands for the classes it names as indistinguishable from it
  // too ("nonlinearity or range_compression: these data cannot tell them apart"): the answer the
  // diagnosis gives where the data cannot separate them (docs/diagnose.md, "Identify").
  bool top_among_indistinguishable = false;
  bool all_among_indistinguishable = false;
  bool nearest_correct = false;    // in-library and unexplained: the nearest is a true one
  int spurious = 0;                // effects named that are not true ones
  bool bias_type = false;          // in-library: BlindTruth::bias_type
  double shrink_pct = 0.0;         // held-out gap RMS, before -> after the named effects
  double excess_shrink_pct = 0.0;  // the part of the held-out gap RMS above the noise
};

// The name a reality's truth gives the effect of a finding ("" for one it has no name for).
using ClassOfFinding = std::function<std::string(const EffectFinding&)>;

// Scores a diagnosis against the truth. An "unexplained" verdict's nearest effect is the
// diagnosis's nearest (the first of `partial` when it gives none).
BlindScore score_blind(const BlindTruth& truth, const Diagnosis& diagnosis,
                       const std::vector<EffectFinding>& partial, const ClassOfFinding& class_of);

// One case run: its diagnosis, what the candidates got when it is unexplained, the score.
struct BlindOutcome {
  Diagnosis diagnosis;
  std::vector<EffectFinding> partial;
  BlindScore score;
  double seconds = 0.0;  // making the sessions plus the diagnosis
};

// ... with the reality's own truth and, when a single case runs (--case), its sessions.
template <class Spec, class Sessions>
struct BlindResult : BlindOutcome {
  Spec spec;
  std::optional<Sessions> sessions;
};

// What the report shows of a case, in the harness's terms.
struct BlindRow {
  int index = 0;  // 1-based
  BlindTruth truth;
  std::string kind_name;   // the reality's name of its kind
  std::string truth_text;  // the truth in a table cell
  double noise_v = 0.0;    // the session noise a table may show, V
  nlohmann::json truth_json;
  const BlindOutcome* outcome = nullptr;
};

// One row of the table by class: the in-library cases that hold the class.
struct BlindClassRow {
  std::string name;
  int pairs = 0, top_correct = 0, named = 0;
  int bias_pairs = 0;                 // of them, cases whose every class is bias-type
  double mean_excess_shrink_pct = 0;  // over those
  int alone = 0, alone_top = 0;       // cases that hold this class only; right top class
  int shared = 0, shared_top = 0, shared_named = 0;  // cases that hold it with others
};

// In-library cases by how many true classes they hold.
struct BlindEffectsRow {
  int effects = 0;  // true classes per case
  int cases = 0, explained = 0, top_correct = 0, all_found = 0;
  int top_among_indistinguishable = 0, all_among_indistinguishable = 0;  // BlindScore's
  int bias_cases = 0;                           // of them, cases whose every class is bias-type
  double mean_excess_shrink_pct = 0;            // over those
  int explained_bias_cases = 0;                 // of those, cases explained
  double mean_explained_excess_shrink_pct = 0;  // over those
};

// A reality's aims for a run (docs/diagnose.md gives their reasons).
struct BlindAims {
  int top_pct = 90;                 // right top effect, % of in-library cases
  double excess_shrink_pct = 70.0;  // mean above-noise shrink of bias-type cases
  bool no_claim_outside = false;    // no claim on outside cases either (always: none on nulls)
  int none_pct = 0;                 // verdict "none", % of null cases (0: no such aim)
};

struct BlindSummary {
  int cases = 0;
  int in_library = 0, top_correct = 0, all_found = 0, spurious = 0;
  int unexplained_in_library = 0, nearest_correct = 0;
  int partly_explained_in_library = 0, partly_top_correct = 0;
  int bias_type = 0;
  double mean_shrink_pct = 0.0, mean_excess_shrink_pct = 0.0;  // over bias-type cases
  int null_cases = 0, null_claims = 0, null_none = 0;
  int outside_cases = 0, outside_claims = 0, outside_unexplained = 0;
  std::vector<BlindClassRow> classes;       // in the order of the reality's class names
  std::vector<BlindEffectsRow> by_effects;  // fewest true classes first
  bool top_aim_met = false, shrink_aim_met = false, claims_aim_met = false, none_aim_met = false;
  bool aims_met() const { return top_aim_met && shrink_aim_met && claims_aim_met && none_aim_met; }
};
BlindSummary summarise_blind(const std::vector<BlindRow>& rows, const BlindAims& aims,
                             const std::vector<std::string>& class_names);

struct SelftestOptions {
  int cases = 10;
  int only_case = 0;  // > 0: run just this case of the seed (to look into one row of a table)
  std::uint64_t seed = 1;
  double duration_s = 0.0;     // <= 0: the protocol's own
  int bootstrap_rounds = 100;  // passed to diagnose()
  int jobs = 0;                // worker threads; 0: the machine's cores
};

// A case's two sessions as the diagnosis reads them.
struct BlindSessions {
  RecordingSeries fit, heldout;
};

// The options case `index` is diagnosed with: the default twin, noise estimated, the run's
// bootstrap rounds, and a bootstrap seed of its own (the run's seed + index), so that a case run
// alone (--case) is diagnosed as in its table and its sessions' files can be diagnosed again the
// same way (`flange diagnose ... --seed S --bootstrap B`).
DiagnoseOptions blind_diagnose_options(int index, const SelftestOptions& options);

// Diagnoses case `index`'s sessions blind (blind_diagnose_options) into `outcome`.
void diagnose_blind(const BlindSessions& sessions, int index, const SelftestOptions& options,
                    BlindOutcome& outcome);

// A reality: what it alone knows of its cases. `Spec` is a case's truth as the reality draws it,
// `Sessions` the two sessions as the reality makes them (kept for a single case, --case).
template <class Spec, class Sessions>
class BlindReality {
 public:
  virtual ~BlindReality() = default;
  // Case `index` (1-based) of options.seed: its truth, drawn from the case's own stream.
  virtual Spec draw(int index, const SelftestOptions& options) const = 0;
  // Its two sessions, made with that truth (options.duration_s: the length or a cap).
  virtual Sessions record(const Spec& spec, const SelftestOptions& options) const = 0;
  // ... as the diagnosis reads them: recordings only, nothing of the truth.
  virtual BlindSessions as_recordings(const Spec& spec, const Sessions& sessions) const = 0;
  // The diagnosis of the case against its truth (score_blind with the reality's names).
  virtual BlindScore score(const Spec& spec, const BlindOutcome& outcome,
                           const Sessions& sessions) const = 0;
  // What the report shows of the case (BlindRow::outcome left unset).
  virtual BlindRow row(const Spec& spec) const = 0;
  virtual BlindAims aims() const = 0;
  // The classes of the table by class, in its order (none: no such table).
  virtual std::vector<std::string> class_names() const = 0;
};

// Every case of options (cases; only_case: just that one), in parallel over options.jobs
// threads; results in case order.
template <class Spec, class Sessions>
std::vector<BlindResult<Spec, Sessions>> run_blind_check(
    const BlindReality<Spec, Sessions>& reality, const SelftestOptions& options) {
  const int count = options.only_case > 0 ? 1 : options.cases;
  std::vector<BlindResult<Spec, Sessions>> results(static_cast<std::size_t>(count));
  run_in_parallel(count, options.jobs, [&](int i) {
    const auto start = std::chrono::steady_clock::now();
    BlindResult<Spec, Sessions>& r = results[static_cast<std::size_t>(i)];
    const int index = options.only_case > 0 ? options.only_case : i + 1;
    r.spec = reality.draw(index, options);
    Sessions sessions = reality.record(r.spec, options);
    diagnose_blind(reality.as_recordings(r.spec, sessions), index, options, r);
    r.score = reality.score(r.spec, r, sessions);
    if (options.only_case > 0) r.sessions = std::move(sessions);
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  });
  return results;
}

// The rows of a run, for the summary and the report.
template <class Spec, class Sessions>
std::vector<BlindRow> blind_rows(const BlindReality<Spec, Sessions>& reality,
                                 const std::vector<BlindResult<Spec, Sessions>>& results) {
  std::vector<BlindRow> rows;
  for (const BlindResult<Spec, Sessions>& r : results) {
    rows.push_back(reality.row(r.spec));
    rows.back().outcome = &r;
  }
  return rows;
}

template <class Spec, class Sessions>
BlindSummary summarise_blind(const BlindReality<Spec, Sessions>& reality,
                             const std::vector<BlindResult<Spec, Sessions>>& results) {
  return summarise_blind(blind_rows(reality, results), reality.aims(), reality.class_names());
}

}  // namespace flange::diagnose
