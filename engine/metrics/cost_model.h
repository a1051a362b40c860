// A cost per kind of work (rays, candidates, ...), fitted to measured times, so that benchmarks
// compare methods by the work they issue (counted, render/frame_work.h) rather than by one
// clock reading each. Times are taken in interleaved rounds (interleaved_rounds.h) and made
// relative to one point of each round (the unit: every cost is a fraction of its time), so a
// machine that slows down during a round scales the whole round and the fit does not see it;
// only the kinds' relative costs matter. The fit is a non-negative least squares over relative
// residuals (Lawson & Hanson, "Solving Least Squares Problems", ch. 23, in its simplest form:
// a negative cost leaves the active set and the rest is refitted): on the per-point medians over
// rounds for the estimate, and per round for the intervals.
#pragma once

#include <cstddef>
#include <span>
#include <utility>
#include <vector>

#include "metrics/interleaved_rounds.h"
#include "metrics/median_interval.h"

namespace engine::metrics {

// The drift (CostModel::ratio) the benches assume by default: the largest between-run movement of
// a kind's relative cost in the eight `vox bench restir` runs of 2026-12-05 on the project's
// shared two-core machine (a light sample on the apartments 12.8-16.5 millionths of ReSTIR's
// frame, 1.29x max / min, so +-14 % around the middle; RIS's equal-cost M 82-136 over the scenes,
// at most 1.26x within one). A measured reproducibility, not a fitted knob: docs/ACCURACY.md
// checks it against every new set of runs.
inline constexpr double kDefaultCostDrift = 0.15;

// The rounds a bench calibrates its cost model in (vox bench restir, vox bench sweep): at least
// 10, so that a cost ratio's interval covers 97 % and, with 5 seeds' min-max of error ratios at
// 93.75 %, the product still covers 90 %; up to 16 while a ratio's half width exceeds 3 %.
inline constexpr RoundsPlan kCostCalibrationRounds{1, 10, 16, 0.97, 0.03};

struct CostModel {
    std::vector<double> perKind;  // cost of one unit of each kind, in the unit point's time
    std::vector<std::vector<double>> perRound;    // [round][kind]: each round's own fit
    std::vector<MedianInterval> perKindInterval;  // over the rounds' fits
    double worstResidual = 0.0;  // largest |model - median time| / median time over the points

    // The cost of `counts` (one per kind) under the medians' fit.
    double cost(std::span<const double> counts) const;
    // cost(a) / cost(b): the estimate as median, the rounds' fits' sign-test interval around it,
    // widened by the drift (widenByDrift).
    MedianInterval ratio(std::span<const double> a, std::span<const double> b, double confidence,
                         double drift = 0.0) const;
    // `m`, an interval of cost(a) / cost(b) from this run's rounds, widened for what the rounds
    // cannot see: the kinds' relative costs differ between runs with what else runs on the cores
    // (a light sample's cost moved 1.29x between runs that each fitted it to a few per cent).
    // Each kind's cost may be off this run's fit by a factor up to (1 + drift) either way,
    // independently; the ratio's extremes over that box are at its corners (a ratio of two linear
    // forms is monotone along every axis), taken relative to m's median. The result spans both:
    // the rounds' interval and the box. Not their product: the drift is the spread of whole runs'
    // fits, noise included, and scaling the rounds' ends by it counted that noise twice — and
    // made an end move with a run's slowest rounds, which flipped a sweep's front between runs
    // (docs/ACCURACY.md). Two points with the same work keep exactly m. `misfit` widens the box
    // by a further factor (1 + misfit) either way: for a ratio measured between two timed points
    // rather than modelled, whose movement between runs is also what the kinds cannot express
    // (unbiased over biased ReSTIR, the same kinds in nearly the same proportion: a box of +-2 %,
    // but 1.04-1.12 measured in four runs); the benches pass the model's worst residual.
    MedianInterval widenByDrift(MedianInterval m, std::span<const double> a,
                                std::span<const double> b, double drift, double misfit = 0.0) const;
    // The extremes of cost(a) / cost(b) over that box alone: {lowest, highest}.
    std::pair<double, double> driftRange(std::span<const double> a, std::span<const double> b,
                                         double drift) const;
};

// counts[point][kind]: the work each measured point issues; times[point][round]: its time in
// each interleaved round (every point measured once per round, all > 0); `unit`: the point
// whose time is 1 in every round.
CostModel fitCostModel(const std::vector<std::vector<double>>& counts,
                       const std::vector<std::vector<double>>& times, std::size_t unit,
                       double confidence = 0.95);

// Non-negative least squares of relative residuals: x >= 0 minimising sum_p ((A x)_p / y_p - 1)^2.
// Kinds no point uses get 0.
std::vector<double> fitRelative(const std::vector<std::vector<double>>& counts,
                                std::span<const double> y);

}  // namespace engine::metrics
