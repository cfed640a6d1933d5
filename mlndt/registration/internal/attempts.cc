#include "mlndt/registration/internal/attempts.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "mlndt/common/pose.h"
#include "mlndt/cost/point_matches.h"
#include "mlndt/cost/score.h"
#include "mlndt/registration/internal/cell_shape.h"
#include "mlndt/registration/internal/direction_probe.h"
#include "mlndt/registration/internal/prior_hold.h"
#include "mlndt/registration/internal/unlocalizable_directions.h"
#include "mlndt/registration/quality_check.h"
#include "mlndt/registration/rival_minima.h"

namespace mlndt {
namespace internal {

const NdtLayer& Problem::planar_last() const {
  if (planar_last_ == nullptr) {
    planar_last_ = std::make_unique<NdtLayer>(WithoutLineCells(last()));
  }
  return *planar_last_;
}

namespace {

// What every step of one registration's runs shares (SolveAttempts'
// arguments): the options, the problem, the initial guess in the anchor's
// frame, the start time and the cost tally.
struct Context {
  const RegistrationOptions& options;
  const Problem& problem;
  const Vector6d& initial_local;
  double start_time_s;
  AttemptsCost* cost;
  // Every solution a run converged to, for the last check (step 7).
  std::vector<Vector6d>* minima;
};

// The fit, constraints and verdict of the attempt's solution.
void Assess(const Context& c, Attempt* attempt) {
  attempt->evaluation = EvaluateScore(c.problem.last(),
                                      c.problem.points,
                                      attempt->xi_local,
                                      c.options.objective);
  Judgement judgement = JudgeSolution(c.options.quality_check,
                                      attempt->schedule.termination_type,
                                      c.problem.last(),
                                      c.problem.points,
                                      attempt->xi_local,
                                      c.options.objective,
                                      c.problem.rms_range_m);
  attempt->fit = judgement.fit;
  attempt->constraints = std::move(judgement.constraints);
  attempt->verdict = judgement.verdict;
  attempt->verdict_message = std::move(judgement.message);
}

// The samples a stage over every stride-th of them evaluates per iteration.
int64_t PointsPerIteration(const Context& c, int stride) {
  const int64_t n = static_cast<int64_t>(c.problem.points.size());
  return (n + stride - 1) / stride;
}

// Adds the point iterations of a schedule run to *cost.
void Count(const Context& c, const ScheduleSummary& schedule) {
  const int n = c.problem.map.num_layers();
  for (int layer = 1; layer <= n; ++layer) {
    const int stride =
        StageControlFor(c.options.schedule, layer, n).point_stride;
    c.cost->point_iterations +=
        schedule.iterations_per_layer[static_cast<size_t>(layer - 1)] *
        PointsPerIteration(c, stride);
  }
}

// Runs the schedule from `start_layer`, adding its point iterations to
// *cost; assesses the solution unless told not to (the guess check assesses
// only a solution in another basin).
Attempt Solve(const Context& c,
              int start_layer,
              const Vector6d& start,
              bool assess = true) {
  Attempt attempt;
  attempt.start_layer = start_layer;
  attempt.xi_local = start;
  RunLayerSchedule(c.options.schedule,
                   start_layer,
                   c.problem.map,
                   c.start_time_s,
                   c.problem.backend,
                   &attempt.xi_local,
                   &attempt.schedule);
  Count(c, attempt.schedule);
  if (attempt.schedule.termination_type == TerminationType::CONVERGENCE) {
    c.minima->push_back(attempt.xi_local);
  }
  if (assess && attempt.schedule.termination_type != TerminationType::FAILURE) {
    Assess(c, &attempt);
  }
  return attempt;
}

// The start layer: from the guess's uncertainty when it is given (the
// displacement it allows at the points' RMS range), else schedule's.
int StartLayer(const Context& c) {
  const InitialGuessUncertainty& u = c.options.initial_uncertainty;
  if (!u.given) {
    return ResolveStartLayer(c.options.schedule, c.problem.map.num_layers());
  }
  const double displacement =
      u.translation_m + u.rotation_deg * kDegToRad * c.problem.rms_range_m;
  return StartLayerForUncertainty(
      c.options.schedule, c.problem.map, displacement);
}

// True when the coarse layers took `xi_local` farther from the guess than
// the last layer alone can check: beyond the guess's uncertainty when it is
// given, else beyond a quarter of a last-layer cell (at the points' RMS range
// for the rotation). A guess within that distance is where the last layer's own
// basin would have led.
bool LeftTheGuess(const Context& c, const Vector6d& xi_local) {
  const InitialGuessUncertainty& u = c.options.initial_uncertainty;
  const Isometry3d guess =
      PoseVectorToIsometry(c.problem.anchor.ToGlobal(c.initial_local));
  const Isometry3d result =
      PoseVectorToIsometry(c.problem.anchor.ToGlobal(xi_local));
  const double moved_m = TranslationErrorM(guess, result);
  const double turned_rad = RotationErrorRad(guess, result);
  if (u.given) {
    return moved_m > u.translation_m || turned_rad > u.rotation_deg * kDegToRad;
  }
  const double quarter_cell_m =
      0.25 * c.problem.map.layer_info().back().cell_size_m;
  return moved_m + turned_rad * c.problem.rms_range_m > quarter_cell_m;
}

// Verdicts from worst to best: a converged, checked pose is what a retry
// looks for; an unconverged one passing the check comes next.
int Rank(const Attempt& attempt) {
  if (attempt.schedule.termination_type == TerminationType::FAILURE) return 0;
  switch (attempt.verdict) {
    case TerminationType::CONVERGENCE:
      return 3;
    case TerminationType::NO_CONVERGENCE:
      return 2;
    default:
      return 1;
  }
}

// `candidate` replaces `best` when its verdict ranks higher, or ranks alike
// and more of its points are inliers. (Not the lower score: points that
// leave the map score nothing, so a pose off the map can score lower.)
// True when it did.
bool KeepBetter(Attempt candidate, Attempt* best) {
  const int rank = Rank(candidate), best_rank = Rank(*best);
  if (rank > best_rank ||
      (rank == best_rank && rank > 0 &&
       candidate.fit.inlier_fraction > best->fit.inlier_fraction)) {
    *best = std::move(candidate);
    return true;
  }
  return false;
}

// Minima more than `cells` last-layer cell edges apart, the rotation
// counted as what it moves a point at the points' RMS range
// (rival_minima.h).
MinimaSeparation SeparationInCells(const Context& c, double cells) {
  MinimaSeparation separation;
  separation.cell_size_m = c.problem.last().cell_size();
  separation.max_cells = cells;
  separation.lever_m = c.problem.rms_range_m;
  return separation;
}

// Two runs that stop within this many last-layer cell edges of each other
// reached one minimum where each stopped: the first is kept, so that the
// result does not flip between the two on round-off.
constexpr double kSameBasinCells = 0.1;

// True when `xi_local` lies in another basin than `best_xi_local`
// (kSameBasinCells apart): of the two, the better fit is kept.
bool AnotherBasin(const Context& c,
                  const Vector6d& xi_local,
                  const Vector6d& best_xi_local) {
  return DistinctMinima(SeparationInCells(c, kSameBasinCells),
                        PoseVectorToIsometry(xi_local),
                        PoseVectorToIsometry(best_xi_local));
}

// Where a stage on `layer` (the last layer, or step 4's planar one) leads
// from *xi_local. False when the stage failed.
bool ExploreFrom(const Context& c,
                 const NdtLayer& layer,
                 const StageControl& control,
                 Vector6d* xi_local) {
  StageSummary stage;
  c.problem.backend->SolveStage(layer, control, xi_local, &stage);
  c.cost->point_iterations +=
      stage.iterations() * PointsPerIteration(c, control.point_stride);
  return stage.termination_type != TerminationType::FAILURE;
}

// The last layer's stage over every s-th sample, s =
// schedule.max_coarse_point_stride: a first look at the cost of a coarse
// stage.
StageControl SubsetControl(const Context& c) {
  const int n = c.problem.map.num_layers();
  StageControl control = StageControlFor(c.options.schedule, n, n);
  control.point_stride = c.options.schedule.max_coarse_point_stride;
  return control;
}

// The last layer alone from `start`, unassessed. A run the iteration cap
// stopped goes on once from where it stopped: a candidate of the search
// starts a cell edge or more from its minimum and can still be sliding along
// a weak direction when the cap ends it, and an unconverged solution cannot
// compete with a converged one.
Attempt SolveLastLayer(const Context& c, const Vector6d& start) {
  const int n = c.problem.map.num_layers();
  Attempt attempt = Solve(c, n, start, /*assess=*/false);
  if (attempt.schedule.termination_type != TerminationType::NO_CONVERGENCE) {
    return attempt;
  }
  Attempt resumed = Solve(c, n, attempt.xi_local, /*assess=*/false);
  ScheduleSummary& s = resumed.schedule;
  s.trace.insert(s.trace.begin(),
                 attempt.schedule.trace.begin(),
                 attempt.schedule.trace.end());
  for (size_t i = 0; i < s.trace.size(); ++i) {
    s.trace[i].iteration = static_cast<int>(i) + 1;
  }
  for (size_t i = 0; i < s.iterations_per_layer.size(); ++i) {
    s.iterations_per_layer[i] += attempt.schedule.iterations_per_layer[i];
  }
  return resumed;
}

// The last layer alone from `start`, first over every s-th sample (s =
// schedule.max_coarse_point_stride) and over all of them only when that
// leads out of best's basin: true, with the (unassessed) solution in
// *candidate, when it converged in another basin than best's.
bool LastLayerInAnotherBasin(const Context& c,
                             Vector6d start,
                             const Attempt& best,
                             Attempt* candidate) {
  if (c.options.schedule.max_coarse_point_stride > 1 &&
      (!ExploreFrom(c, c.problem.last(), SubsetControl(c), &start) ||
       !AnotherBasin(c, start, best.xi_local))) {
    return false;
  }
  *candidate = SolveLastLayer(c, start);
  return candidate->schedule.termination_type != TerminationType::FAILURE &&
         AnotherBasin(c, candidate->xi_local, best.xi_local);
}

// A solution found by the search replaces best only when it has more
// inliers by at least this many standard deviations of the points that
// changed (InlierGainEvidence): among the minima of a wide, flat basin the
// inlier count differs by chance, and a smaller margin swaps a right result
// for another one nearby.
constexpr double kMinInlierGainEvidence = 1.0;

// More inliers at all (InlierGainEvidence > 0): what a minimum beyond the
// scan pattern needs (step 4).
constexpr double kAnyInlierGain = std::numeric_limits<double>::min();

// How clearly `to` fits `layer` better than `from`: the points that are
// inliers at `to` and not at `from`, net of the reverse, over the square
// root of all that changed (a z-score, as the probe's evidence).
double InlierGainEvidence(const Context& c,
                          const NdtLayer& layer,
                          const Vector6d& from,
                          const Vector6d& to) {
  const Isometry3d a = PoseVectorToIsometry(from);
  const Isometry3d b = PoseVectorToIsometry(to);
  const double gate = c.options.quality_check.inlier_gate;
  const UnmatchedPolicy policy = c.options.objective.unmatched_policy;
  double gained = 0.0, lost = 0.0;
  for (const Eigen::Vector3d& p : c.problem.points) {
    const bool at_a = MatchPoint(layer, a * p, policy).IsInlier(gate);
    const bool at_b = MatchPoint(layer, b * p, policy).IsInlier(gate);
    gained += at_b && !at_a;
    lost += at_a && !at_b;
  }
  return (gained - lost) / std::sqrt(std::max(gained + lost, 1.0));
}

// The translation of reference_from_input at `xi_local`: where the input's
// sensor lies in the reference's frame.
Eigen::Vector3d SensorPosition(const Context& c, const Vector6d& xi_local) {
  return c.problem.anchor.ToGlobal(xi_local).head<3>();
}

// True when step 4 applies to `attempt`: converged, its translation within
// retry.scan_pattern_reach_cells last-layer cell edges of zero.
bool AtZeroMotion(const Context& c, const Attempt& attempt) {
  const double reach_m =
      c.options.retry.scan_pattern_reach_cells * c.problem.last().cell_size();
  return attempt.verdict == TerminationType::CONVERGENCE &&
         SensorPosition(c, attempt.xi_local).norm() <= reach_m;
}

// True when the planar cells (Problem::planar_last) hold clearly more
// inliers (kMinInlierGainEvidence) at `other` than at `current`: the
// evidence that counts where the sensors coincide (step 4), for there the
// rings fit `current` whatever the motion.
bool PlanarCellsPrefer(const Context& c,
                       const Attempt& current,
                       const Attempt& other) {
  return InlierGainEvidence(
             c, c.problem.planar_last(), current.xi_local, other.xi_local) >=
         kMinInlierGainEvidence;
}

// True when `other` (assessed) converged with more inliers on the last layer
// than `current` by at least `min_gain` (InlierGainEvidence).
bool ConvergedWithMoreInliers(const Context& c,
                              const Attempt& current,
                              const Attempt& other,
                              double min_gain) {
  return other.verdict == TerminationType::CONVERGENCE &&
         InlierGainEvidence(
             c, c.problem.last(), current.xi_local, other.xi_local) >= min_gain;
}

// `other` (assessed) replaces *current, a result where the sensors
// coincide. Its verdict stands unless it converged with no more inliers on
// the whole last layer (only the planar cells prefer it): then the rings and
// the planes disagree, and it is LOW_QUALITY.
void ReplacePatternMinimum(const Context& c, Attempt other, Attempt* current) {
  if (other.verdict == TerminationType::CONVERGENCE &&
      !ConvergedWithMoreInliers(c, *current, other, kAnyInlierGain)) {
    other.verdict = TerminationType::LOW_QUALITY;
    other.verdict_message =
        "the scan pattern and the scene disagree: where the two sensors "
        "nearly coincide a spinning LiDAR's rings fit better, but the map's "
        "planar cells prefer this pose";
  }
  *current = std::move(other);
}

// Step 2 above. The last layer alone runs from the guess; when it stays in
// best's basin, the guess leads there too and the check ends. Otherwise
// that solution, assessed, replaces best if it fits better: on the planar
// cells when best converged where the sensors coincide (the coarse layers
// can carry a guess into the pattern's minimum), else by KeepBetter.
void CompareWithLastLayerFromGuess(const Context& c, Attempt* best) {
  ++c.cost->attempts;
  Attempt from_guess;
  if (LastLayerInAnotherBasin(c, c.initial_local, *best, &from_guess)) {
    Assess(c, &from_guess);
    if (AtZeroMotion(c, *best) && PlanarCellsPrefer(c, *best, from_guess)) {
      ReplacePatternMinimum(c, std::move(from_guess), best);
    } else {
      KeepBetter(std::move(from_guess), best);
    }
  }
}

// Whether `other`, an assessed solution in another basin than `current`'s
// (LastLayerInAnotherBasin), fits better than `current`.
using Preference = bool (*)(const Context& c,
                            const Attempt& current,
                            const Attempt& other);

// Steps 3 and 4's first part: converged, with clearly more inliers on the
// last layer (kMinInlierGainEvidence), and an objective (Eq. 10 with the
// robust loss, on the last layer) no higher than current's: in a wide
// basin a minimum nearby can gain inliers at the gate's edge while the bulk
// of the points fits worse. The score alone does not decide, since a point
// that leaves the map scores nothing.
bool ClearlyMoreInliers(const Context& c,
                        const Attempt& current,
                        const Attempt& other) {
  return ConvergedWithMoreInliers(c, current, other, kMinInlierGainEvidence) &&
         other.evaluation.score <= current.evaluation.score;
}

// Step 4's second part, beyond the pattern: where the sensors coincide the
// pattern adds inliers to `current`, so a converged `other` with more
// inliers at all (kAnyInlierGain) fits better, and so does one the planar
// cells prefer.
bool FitsBetterThanPatternMinimum(const Context& c,
                                  const Attempt& current,
                                  const Attempt& other) {
  return ConvergedWithMoreInliers(c, current, other, kAnyInlierGain) ||
         PlanarCellsPrefer(c, current, other);
}

// True when `other`, a solution in another basin than `current`'s, may
// replace it: assessed here, within the guess's uncertainty when one is
// given, and `prefer`red.
bool FitsBetter(const Context& c,
                const Attempt& current,
                Preference prefer,
                Attempt* other) {
  if (c.options.initial_uncertainty.given && LeftTheGuess(c, other->xi_local)) {
    return false;
  }
  Assess(c, other);
  return prefer(c, current, *other);
}

// The last layer from `current` moved `step_m` along d, then along -d (over
// a subset of the samples first, as the guess check): true, with it in
// *found, at the first solution in another basin that FitsBetter.
bool BetterMinimumAlong(const Context& c,
                        const Attempt& current,
                        const Vector6d& d,
                        double step_m,
                        Preference prefer,
                        Attempt* found) {
  for (const double sign : {1.0, -1.0}) {
    ++c.cost->attempts;
    const Vector6d start =
        IsometryToPoseVector(MovedAlong(PoseVectorToIsometry(current.xi_local),
                                        sign * d,
                                        step_m,
                                        c.problem.rms_range_m));
    if (LastLayerInAnotherBasin(c, start, current, found) &&
        FitsBetter(c, current, prefer, found)) {
      return true;
    }
  }
  return false;
}

// One round of the search along best's flattest weak direction, one cell
// edge each way; true when a solution in another basin replaced best.
bool BetterMinimumAlongFlattest(const Context& c, Attempt* best) {
  const Vector6d d = best->constraints.flattest_direction;
  if (d.isZero() || best->constraints.flatness <
                        c.options.retry.weak_direction_min_flatness) {
    return false;
  }
  Attempt moved;
  return BetterMinimumAlong(c,
                            *best,
                            d,
                            c.problem.last().cell_size(),
                            ClearlyMoreInliers,
                            &moved) &&
         KeepBetter(std::move(moved), best);
}

// Step 3 above: rounds of BetterMinimumAlongFlattest while the result converged
// and the last round found a better minimum.
void SearchAlongFlattestDirection(const Context& c, Attempt* best) {
  for (int round = 0; round < c.options.retry.weak_direction_rounds; ++round) {
    if (best->verdict != TerminationType::CONVERGENCE ||
        !BetterMinimumAlongFlattest(c, best)) {
      return;
    }
  }
}

// Step 4's first part: where the planar cells alone lead from *attempt.
// True when *attempt stands; false when a clearly better solution replaced
// it or it was flagged LOW_QUALITY.
bool PlanarCellsReturn(const Context& c, Attempt* attempt) {
  const NdtLayer& planar = c.problem.planar_last();
  // The last layer's stage over the samples and iterations of the layer
  // before it (a sparser subset moves on its own sampling noise); a
  // one-layer map's own.
  const int n = c.problem.map.num_layers();
  const StageControl before_last =
      StageControlFor(c.options.schedule, std::max(1, n - 1), n);
  StageControl control = StageControlFor(c.options.schedule, n, n);
  control.point_stride = before_last.point_stride;
  control.max_iterations = before_last.max_iterations;
  Vector6d led = attempt->xi_local;
  if (!ExploreFrom(c, planar, control, &led)) return true;
  // The pattern holds the sensor's position: only a translation by more
  // than kSameBasinCells counts (without the ground's rings the planar
  // cells may tilt the pose a little).
  const double led_m =
      (SensorPosition(c, led) - SensorPosition(c, attempt->xi_local)).norm();
  if (led_m <= kSameBasinCells * c.problem.last().cell_size()) return true;
  Attempt other;
  if (LastLayerInAnotherBasin(c, led, *attempt, &other)) {
    if (FitsBetter(c, *attempt, ClearlyMoreInliers, &other)) {
      *attempt = std::move(other);
      return false;
    }
  } else if (InlierGainEvidence(c, planar, attempt->xi_local, led) < 0.0) {
    return true;
  }
  attempt->verdict = TerminationType::LOW_QUALITY;
  attempt->verdict_message =
      "the fit may rest on the scan pattern: the pose is where the two "
      "sensors nearly coincide (and so do a spinning LiDAR's rings), and "
      "the map's planar cells alone lead elsewhere";
  return false;
}

// Step 4's second part: the scene's own minimum may lie beyond the
// pattern's, along d, the translation the planar cells constrain least.
// Only where they keep as many of their inliers one cell edge along d
// (ProbeAlong, direction_probe.h) as the search (step 3) needs of the
// flattest direction can such a minimum lie near. The last layer runs from
// the result moved along d and back by (1 + reach) cell edges: out of the
// pattern's reach and of its neighbouring cells' pull. A minimum in another
// basin that FitsBetterThanPatternMinimum replaces the result
// (ReplacePatternMinimum).
void SearchBeyondPatternReach(const Context& c, Attempt* attempt) {
  Vector6d d = Vector6d::Zero();
  d.head<3>() = attempt->constraints.weakest_translations.col(0);
  if (d.isZero() ||
      ProbeAlong(c.problem.planar_last(),
                 c.problem.points,
                 attempt->xi_local,
                 c.options.objective,
                 c.problem.rms_range_m,
                 c.options.quality_check.inlier_gate,
                 d)
              .kept < c.options.retry.weak_direction_min_flatness) {
    return;
  }
  Attempt found;
  if (BetterMinimumAlong(c,
                         *attempt,
                         d,
                         (1.0 + c.options.retry.scan_pattern_reach_cells) *
                             c.problem.last().cell_size(),
                         FitsBetterThanPatternMinimum,
                         &found)) {
    ReplacePatternMinimum(c, std::move(found), attempt);
  }
}

// Step 4 above, on a converged *attempt where the sensors nearly coincide.
void CheckPatternMinimum(const Context& c, Attempt* attempt) {
  if (!AtZeroMotion(c, *attempt)) return;
  ++c.cost->attempts;
  if (PlanarCellsReturn(c, attempt)) {
    SearchBeyondPatternReach(c, attempt);
  }
}

// Two minima more than this many last-layer cell edges apart are distinct:
// within half a cell most points keep their cells.
constexpr double kDistinctMinimaCells = 0.5;

// A distinct minimum fits as well as the result unless it holds clearly
// fewer inliers on the last layer (InlierGainEvidence below minus this
// many standard deviations).
constexpr double kAsGoodInlierEvidence = 1.0;

// From pose a to pose b as the constraint rows scale it: the translation,
// and the rotation vector times `lever_m`.
Vector6d ScaledDifference(const Isometry3d& a,
                          const Isometry3d& b,
                          double lever_m) {
  const Eigen::AngleAxisd turn(b.linear() * a.linear().transpose());
  Vector6d d;
  d << b.translation() - a.translation(), turn.angle() * lever_m * turn.axis();
  return d;
}

// Step 7 above: a converged result is DEGENERATE when a distinct minimum
// that a run converged to fits as well (FindRivalMinimum): the data do not
// decide between the two. The direction from the result to it is named,
// and unbounded in the covariance.
void FlagRivalMinimum(const Context& c, Attempt* best) {
  if (best->verdict != TerminationType::CONVERGENCE) return;
  std::vector<Isometry3d> minima = {PoseVectorToIsometry(best->xi_local)};
  for (const Vector6d& minimum : *c.minima) {
    minima.push_back(PoseVectorToIsometry(minimum));
  }
  RivalMinimaOptions options;
  options.separation = SeparationInCells(c, kDistinctMinimaCells);
  options.as_well_margin = kAsGoodInlierEvidence;
  // The fit: the inlier gain's z-score from the result (0 at the result).
  const RivalMinimaSummary rival =
      FindRivalMinimum(options, minima, 0, [&](size_t i) {
        if (i == 0) return 0.0;
        return InlierGainEvidence(
            c, c.problem.last(), best->xi_local, (*c.minima)[i - 1]);
      });
  if (!rival.found()) return;
  const Vector6d d = ScaledDifference(minima[0],
                                      minima[static_cast<size_t>(rival.rival)],
                                      c.problem.rms_range_m);
  char apart[64];
  std::snprintf(apart,
                sizeof(apart),
                "%.2f m and %.2f deg",
                rival.apart_m,
                rival.apart_deg);
  best->constraints.degenerate_directions.push_back(d.normalized());
  best->verdict = TerminationType::DEGENERATE;
  best->verdict_message =
      std::string(
          "degenerate: the fit does not decide between this pose "
          "and another minimum ") +
      apart + " away (" + DescribeDirection(d) + ") with about as many inliers";
}

// Step 6 above: a usable result is DEGENERATE when the surfaces its
// inliers lie on leave a translation free (localizability.h; `check`'s
// min_localizability). Judged once, on the chosen minimum: the searches of
// steps 2-5 look for the best minimum, and whether the geometry pins it
// down is a property of that minimum, not of the starts on the way.
void FlagUnlocalizable(const Context& c,
                       const QualityCheckOptions& check,
                       Attempt* best) {
  if (!best->usable() || !(check.min_localizability > 0.0)) return;
  Judgement judgement = JudgeSolution(check,
                                      best->schedule.termination_type,
                                      c.problem.last(),
                                      c.problem.points,
                                      best->xi_local,
                                      c.options.objective,
                                      c.problem.rms_range_m);
  if (judgement.verdict != TerminationType::DEGENERATE) return;
  best->constraints = std::move(judgement.constraints);
  best->verdict = judgement.verdict;
  best->verdict_message = std::move(judgement.message);
}

// Step 8's free directions, all of them: a result DEGENERATE by the ratio,
// the probe or a rival minimum was judged without the localizability test
// (steps 1-5, 7), so the translations it leaves free join its degenerate
// directions here (AddUnlocalizableDirections, as the verdict adds them),
// unless already named. Only with a prior: without one the verdict already
// says free.
void AddFreeTranslations(const RegistrationOptions& options,
                         const Problem& problem,
                         Attempt* best) {
  if (!options.initial_uncertainty.given ||
      best->verdict != TerminationType::DEGENERATE ||
      !(options.quality_check.min_localizability > 0.0)) {
    return;
  }
  const std::vector<Vector6d> added = AddUnlocalizableDirections(
      MatchAtSolution(
          problem.last(), problem.points, best->xi_local, options.objective),
      options.quality_check,
      &best->constraints);
  for (const Vector6d& d : added) {
    best->verdict_message += "; also free: " + DescribeDirection(d);
  }
}

// Step 8 above (prior_hold.h), its message added to the verdict's.
void HoldPrior(const RegistrationOptions& options,
               const Problem& problem,
               const Vector6d& initial_local,
               Attempt* best) {
  AddFreeTranslations(options, problem, best);
  if (HoldPriorAlongFreeDirections(options, problem, initial_local, best) > 0) {
    best->verdict_message +=
        "; the pose keeps the prior's value along the free directions, and "
        "the covariance the prior's there";
  }
}

// The guess turned by `yaw_deg` about the z axis at the input's centroid.
Vector6d TurnedGuess(const Vector6d& guess, double yaw_deg) {
  Isometry3d turned = PoseVectorToIsometry(guess);
  turned.linear() =
      Eigen::AngleAxisd(yaw_deg * kDegToRad, Eigen::Vector3d::UnitZ()) *
      turned.linear();
  return IsometryToPoseVector(turned);
}

}  // namespace

Attempt SolveAttempts(const RegistrationOptions& options,
                      const Problem& problem,
                      const Vector6d& initial_local,
                      double start_time_s,
                      AttemptsCost* cost) {
  std::vector<Vector6d> minima;
  // Steps 1-5 judge each run without the localizability test (step 6).
  RegistrationOptions searching = options;
  searching.quality_check.min_localizability = 0.0;
  const Context c{
      searching, problem, initial_local, start_time_s, cost, &minima};
  const int n = problem.map.num_layers();
  const int start = StartLayer(c);
  Attempt best = Solve(c, start, initial_local);
  cost->attempts = 1;
  if (best.schedule.termination_type == TerminationType::FAILURE) return best;
  const InitialGuessUncertainty& u = options.initial_uncertainty;
  if (start < n && LeftTheGuess(c, best.xi_local))
    CompareWithLastLayerFromGuess(c, &best);
  SearchAlongFlattestDirection(c, &best);
  CheckPatternMinimum(c, &best);
  for (const double yaw_deg : options.retry.yaw_seeds_deg) {
    if (best.verdict == TerminationType::CONVERGENCE) break;
    if (u.given && std::abs(yaw_deg) > u.rotation_deg) continue;
    ++cost->attempts;
    Attempt turned = Solve(c, start, TurnedGuess(initial_local, yaw_deg));
    CheckPatternMinimum(c, &turned);
    KeepBetter(std::move(turned), &best);
  }
  FlagUnlocalizable(c, options.quality_check, &best);
  FlagRivalMinimum(c, &best);
  HoldPrior(options, problem, initial_local, &best);
  return best;
}

}  // namespace internal
}  // namespace mlndt
