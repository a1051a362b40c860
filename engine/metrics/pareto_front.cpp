#include "metrics/pareto_front.h"

#include "metrics/seed_statistics.h"

namespace engine::metrics {

std::string_view frontStatusName(FrontStatus s) {
    switch (s) {
        case FrontStatus::Member:
            return "member";
        case FrontStatus::Unresolved:
            return "unresolved";
        case FrontStatus::Dominated:
            return "dominated";
    }
    return "?";
}

std::vector<FrontStatus> paretoFront(const FrontInput& in) {
    const std::size_t n = in.errors.size();
    std::vector<FrontStatus> out(n, FrontStatus::Member);
    for (std::size_t p = 0; p < n; ++p) {
        for (std::size_t q = 0; q < n && out[p] != FrontStatus::Dominated; ++q) {
            if (q == p) continue;
            const MedianInterval cost = in.costRatio(q, p);
            const Verdict costVerdict = verdictOf(cost, in.confidence, in.noise);
            const Verdict errorVerdict =
                verdictOf(medianInterval(perSeedRatios(in.errors[q], in.errors[p]), in.confidence),
                          in.confidence, in.noise);
            // Surely: q costs no more in every plausible case (its interval's top at most 1, as
            // for the same work) and is more accurate beyond the noise.
            const bool noDearer = cost.high <= 1.0 || costVerdict == Verdict::Below;
            if (noDearer && errorVerdict == Verdict::Below) {
                out[p] = FrontStatus::Dominated;
            } else if (costVerdict != Verdict::Above && errorVerdict != Verdict::Above) {
                out[p] = FrontStatus::Unresolved;  // q may dominate p: not excluded either way
            }
        }
    }
    return out;
}

}  // namespace engine::metrics
