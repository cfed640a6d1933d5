#include "mlndt/pipeline/localization_prior.h"

#include <glog/logging.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "mlndt/common/pose.h"
#include "mlndt/common/timer.h"
#include "mlndt/registration/prepared_input.h"
#include "mlndt/registration/prepared_registration.h"
#include "mlndt/registration/rival_minima.h"

namespace mlndt {
namespace {

bool Fail(const char* message, std::string* error) {
  if (error != nullptr) *error = message;
  return false;
}

// Step 1: the starts on the prior's half-bound (none when one basin holds
// the prior).
std::vector<Isometry3d> ExploreStarts(const PriorCheckOptions& options,
                                      const InitialGuessUncertainty& prior,
                                      double finest_cell_m,
                                      const Isometry3d& guess) {
  if (!options.explore) return {};
  const double step_m =
      prior.translation_m > finest_cell_m ? 0.5 * prior.translation_m : 0.0;
  const double turn_deg = prior.rotation_deg > options.explore_min_rotation_deg
                              ? 0.5 * prior.rotation_deg
                              : 0.0;
  return StartsAround(guess, step_m, turn_deg);
}

// Step 2's order: more inliers, then a lower mean score.
bool FitsBetter(const RegistrationSummary& a, const RegistrationSummary& b) {
  if (a.quality.inlier_fraction != b.quality.inlier_fraction) {
    return a.quality.inlier_fraction > b.quality.inlier_fraction;
  }
  return a.quality.mean_score < b.quality.mean_score;
}

// Step 3: another kept minimum, distinct from kept[best] (farther than half
// a finest cell edge or explore_distinct_rotation_deg), whose inlier
// fraction is within ambiguity_inlier_margin of it (rival_minima.h).
const RegistrationSummary* Rival(const PriorCheckOptions& options,
                                 const std::vector<RegistrationSummary>& kept,
                                 size_t best) {
  RivalMinimaOptions rival_options;
  rival_options.separation.cell_size_m = kept[best].finest_cell_size_m;
  rival_options.separation.max_cells = 0.5;
  rival_options.separation.max_rotation_deg =
      options.explore_distinct_rotation_deg;
  rival_options.as_well_margin = options.ambiguity_inlier_margin;
  std::vector<Isometry3d> minima;
  for (const RegistrationSummary& s : kept) {
    minima.push_back(s.reference_from_input);
  }
  const RivalMinimaSummary rival =
      FindRivalMinimum(rival_options, minima, best, [&](size_t i) {
        return kept[i].quality.inlier_fraction;
      });
  return rival.found() ? &kept[static_cast<size_t>(rival.rival)] : nullptr;
}

void Demote(TerminationType type,
            const std::string& why,
            RegistrationSummary* summary) {
  summary->message = why + " (the registration said " +
                     TerminationTypeToString(summary->termination_type) + ": " +
                     summary->message + ")";
  summary->termination_type = type;
}

// The inlier fraction among the points whose own cell the map holds: what
// the map can explain at any pose. A scan that sees beyond the mapped
// region keeps the points outside out of the comparison with the map's own
// points (its inlier_fraction alone would call a right pose of a scan that
// reaches past a one-frame map a poor fit).
double CoveredInlierFraction(const FitQuality& quality) {
  if (quality.own_cell_fraction <= 0.0) return 0.0;
  return std::min(1.0, quality.inlier_fraction / quality.own_cell_fraction);
}

void DemoteNotKept(const InitialGuessUncertainty& prior,
                   const Isometry3d& guess,
                   double min_inliers,
                   RegistrationSummary* summary) {
  char why[240];
  std::snprintf(
      why,
      sizeof(why),
      "no usable result within the prior fits the map as its own points do "
      "(inliers >= %.3f): the registration's is %.2f m, %.1f deg from the "
      "guess (prior %.2f m, %.1f deg), inliers %.3f; outside the prior or a "
      "look-alike place",
      min_inliers,
      TranslationErrorM(guess, summary->reference_from_input),
      RotationErrorRad(guess, summary->reference_from_input) * kRadToDeg,
      prior.translation_m,
      prior.rotation_deg,
      CoveredInlierFraction(summary->quality));
  Demote(TerminationType::LOW_QUALITY, why, summary);
}

void DemoteAmbiguous(const RegistrationSummary& rival,
                     RegistrationSummary* summary) {
  char why[200];
  std::snprintf(
      why,
      sizeof(why),
      "another minimum within the prior fits as well: %.2f m, %.1f deg away, "
      "inliers %.3f against %.3f",
      TranslationErrorM(summary->reference_from_input,
                        rival.reference_from_input),
      RotationErrorRad(summary->reference_from_input,
                       rival.reference_from_input) *
          kRadToDeg,
      rival.quality.inlier_fraction,
      summary->quality.inlier_fraction);
  Demote(TerminationType::DEGENERATE, why, summary);
}

}  // namespace

bool PriorCheckOptions::IsValid(std::string* error) const {
  if (!(explore_min_rotation_deg >= 0.0 && explore_min_rotation_deg <= 180.0))
    return Fail("explore_min_rotation_deg must be in [0, 180]", error);
  if (!(explore_distinct_rotation_deg > 0.0 &&
        explore_distinct_rotation_deg <= 180.0))
    return Fail("explore_distinct_rotation_deg must be in (0, 180]", error);
  if (!(ambiguity_inlier_margin >= 0.0 && ambiguity_inlier_margin <= 1.0))
    return Fail("ambiguity_inlier_margin must be in [0, 1]", error);
  if (!(min_fit_ratio >= 0.0 && min_fit_ratio <= 1.0))
    return Fail("min_fit_ratio must be in [0, 1]", error);
  return true;
}

double GaussianInlierShare(double gate) {
  // chi2 with 3 degrees of freedom: erf(g / sqrt 2) - sqrt(2 / pi) g
  // e^(-g^2/2).
  return std::erf(gate / std::sqrt(2.0)) -
         std::sqrt(2.0 / M_PI) * gate * std::exp(-0.5 * gate * gate);
}

bool WithinPrior(const InitialGuessUncertainty& prior,
                 const Isometry3d& guess,
                 const Isometry3d& pose) {
  if (!prior.given) return true;
  return TranslationErrorM(guess, pose) <= prior.translation_m &&
         RotationErrorRad(guess, pose) * kRadToDeg <= prior.rotation_deg;
}

void RegisterWithinPrior(const PriorCheckOptions& options,
                         const RegistrationOptions& registration,
                         const LayeredGrid& map,
                         const PointCloud& scan,
                         const Isometry3d& guess,
                         const InitialGuessUncertainty& prior,
                         RegistrationSummary* summary,
                         PriorCheckSummary* check) {
  CHECK(summary != nullptr);
  PriorCheckSummary local;
  PriorCheckSummary& c = check != nullptr ? *check : local;
  c = PriorCheckSummary();
  if (!prior.given) {
    // The registration's verdict stands.
    Register(registration, map, scan, guess, summary);
    return;
  }
  RegistrationOptions with_prior = registration;
  with_prior.initial_uncertainty = prior;
  // Every run registers the same samples with the same options: the scan
  // is filtered and sampled once (prepared_input.h), and the solver set up
  // once (prepared_registration.h).
  const double prepare_start_s = NowSeconds();
  PreparedInput prepared;
  PrepareInput(with_prior, scan, &prepared);
  PreparedRegistration runs(with_prior, prepared);
  const double prepare_time_s = NowSeconds() - prepare_start_s;
  runs.Register(map, guess, summary);
  const double min_inliers =
      options.min_fit_ratio *
      GaussianInlierShare(registration.quality_check.inlier_gate);

  // Step 2: every usable result within the prior that fits as the map's
  // own points do, the first run's first.
  std::vector<RegistrationSummary> kept;
  const auto keep = [&](const RegistrationSummary& s) {
    if (s.IsSolutionUsable() &&
        WithinPrior(prior, guess, s.reference_from_input) &&
        CoveredInlierFraction(s.quality) >= min_inliers) {
      kept.push_back(s);
    }
  };
  keep(*summary);
  const bool first_kept = !kept.empty();
  for (const Isometry3d& start :
       ExploreStarts(options, prior, summary->finest_cell_size_m, guess)) {
    RegistrationSummary s;
    runs.Register(map, start, &s);
    ++c.explored_starts;
    c.explored_time_s += s.total_time_s;
    keep(s);
  }
  c.usable_within = static_cast<int>(kept.size());
  // The scan's time is the preparation's and every run's (solve_time_s
  // stays the kept run's).
  const double all_runs_s =
      prepare_time_s + summary->total_time_s + c.explored_time_s;

  if (kept.empty()) {
    // Step 4: nothing usable within the prior fits the map well enough.
    if (summary->IsSolutionUsable()) {
      DemoteNotKept(prior, guess, min_inliers, summary);
    }
  } else {
    size_t best = 0;
    for (size_t i = 1; i < kept.size(); ++i) {
      if (FitsBetter(kept[i], kept[best])) best = i;
    }
    c.moved_to_other_start = !first_kept || best != 0;
    const RegistrationSummary* rival = Rival(options, kept, best);
    *summary = kept[best];
    if (rival != nullptr) DemoteAmbiguous(*rival, summary);
  }
  summary->total_time_s = all_runs_s;
  c.from_guess_m = TranslationErrorM(guess, summary->reference_from_input);
  c.from_guess_deg =
      RotationErrorRad(guess, summary->reference_from_input) * kRadToDeg;
}

}  // namespace mlndt
