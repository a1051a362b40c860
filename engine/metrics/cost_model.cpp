#include "metrics/cost_model.h"

#include <algorithm>
#include <cmath>

#include "metrics/seed_statistics.h"

namespace engine::metrics {

namespace {

// Solves the square system m x = b by Gaussian elimination with partial pivoting; false when
// singular.
bool solve(std::vector<std::vector<double>> m, std::vector<double> b, std::vector<double>& x) {
    const std::size_t n = b.size();
    for (std::size_t c = 0; c < n; ++c) {
        std::size_t pivot = c;
        for (std::size_t r = c + 1; r < n; ++r) {
            if (std::abs(m[r][c]) > std::abs(m[pivot][c])) pivot = r;
        }
        if (!(std::abs(m[pivot][c]) > 1e-12)) return false;
        std::swap(m[c], m[pivot]);
        std::swap(b[c], b[pivot]);
        for (std::size_t r = c + 1; r < n; ++r) {
            const double f = m[r][c] / m[c][c];
            for (std::size_t k = c; k < n; ++k) m[r][k] -= f * m[c][k];
            b[r] -= f * b[c];
        }
    }
    x.assign(n, 0.0);
    for (std::size_t c = n; c-- > 0;) {
        double s = b[c];
        for (std::size_t k = c + 1; k < n; ++k) s -= m[c][k] * x[k];
        x[c] = s / m[c][c];
    }
    return true;
}

// Least squares over the kinds in `active` (columns scaled to 1 for conditioning); rows are the
// points' counts divided by their times, the targets 1.
std::vector<double> leastSquares(const std::vector<std::vector<double>>& rows,
                                 const std::vector<std::size_t>& active, std::size_t kinds) {
    const std::size_t n = active.size();
    std::vector<double> scale(n, 0.0);
    for (std::size_t j = 0; j < n; ++j) {
        for (const auto& r : rows) scale[j] = std::max(scale[j], std::abs(r[active[j]]));
    }
    std::vector<std::vector<double>> ata(n, std::vector<double>(n, 0.0));
    std::vector<double> atb(n, 0.0);
    for (const auto& r : rows) {
        for (std::size_t i = 0; i < n; ++i) {
            const double ai = r[active[i]] / scale[i];
            atb[i] += ai;
            for (std::size_t j = 0; j < n; ++j) ata[i][j] += ai * r[active[j]] / scale[j];
        }
    }
    // A ridge far below the data's scale: an underdetermined fit (two points, four kinds) gets the
    // smallest solution instead of none, and a determined one is not moved measurably.
    double trace = 0.0;
    for (std::size_t i = 0; i < n; ++i) trace += ata[i][i];
    for (std::size_t i = 0; i < n; ++i)
        ata[i][i] += 1e-9 * trace / double(std::max<std::size_t>(n, 1));
    std::vector<double> x(kinds, 0.0), z;
    if (!solve(ata, atb, z)) return x;
    for (std::size_t j = 0; j < n; ++j) x[active[j]] = z[j] / scale[j];
    return x;
}

}  // namespace

std::vector<double> fitRelative(const std::vector<std::vector<double>>& counts,
                                std::span<const double> y) {
    const std::size_t kinds = counts.empty() ? 0 : counts[0].size();
    std::vector<std::vector<double>> rows;
    for (std::size_t p = 0; p < counts.size(); ++p) {
        std::vector<double> r(kinds);
        for (std::size_t k = 0; k < kinds; ++k) r[k] = counts[p][k] / y[p];
        rows.push_back(r);
    }
    std::vector<std::size_t> active;
    for (std::size_t k = 0; k < kinds; ++k) {
        if (std::any_of(counts.begin(), counts.end(), [&](const auto& c) { return c[k] > 0.0; }))
            active.push_back(k);
    }
    for (;;) {
        std::vector<double> x = leastSquares(rows, active, kinds);
        auto worst = std::min_element(active.begin(), active.end(),
                                      [&](std::size_t a, std::size_t b) { return x[a] < x[b]; });
        if (worst == active.end() || x[*worst] >= 0.0) return x;
        active.erase(worst);  // a negative cost: that kind is free at this precision
    }
}

double CostModel::cost(std::span<const double> counts) const {
    double c = 0.0;
    for (std::size_t k = 0; k < perKind.size() && k < counts.size(); ++k)
        c += perKind[k] * counts[k];
    return c;
}

std::pair<double, double> CostModel::driftRange(std::span<const double> a,
                                                std::span<const double> b, double drift) const {
    const std::size_t kinds = perKind.size();
    double lowest = 0.0, highest = 0.0;
    bool any = false;
    for (std::size_t corner = 0; corner < (std::size_t(1) << kinds); ++corner) {
        double ca = 0.0, cb = 0.0;
        for (std::size_t k = 0; k < kinds; ++k) {
            const double x = perKind[k] * ((corner >> k) & 1 ? 1.0 + drift : 1.0 / (1.0 + drift));
            if (k < a.size()) ca += x * a[k];
            if (k < b.size()) cb += x * b[k];
        }
        if (!(cb > 0.0)) continue;
        const double r = ca / cb;
        lowest = any ? std::min(lowest, r) : r;
        highest = any ? std::max(highest, r) : r;
        any = true;
    }
    return {lowest, highest};
}

MedianInterval CostModel::ratio(std::span<const double> a, std::span<const double> b,
                                double confidence, double drift) const {
    auto costOf = [](const std::vector<double>& x, std::span<const double> counts) {
        double c = 0.0;
        for (std::size_t k = 0; k < x.size() && k < counts.size(); ++k) c += x[k] * counts[k];
        return c;
    };
    std::vector<double> perRoundRatios;
    for (const std::vector<double>& x : perRound) {
        const double cb = costOf(x, b);
        if (cb > 0.0) perRoundRatios.push_back(costOf(x, a) / cb);
    }
    MedianInterval out = medianInterval(perRoundRatios, confidence);
    // The estimate is the medians' fit; the interval the rounds' (widened to hold the estimate).
    out.median = cost(a) / cost(b);
    out.low = std::min(out.low, out.median);
    out.high = std::max(out.high, out.median);
    return widenByDrift(out, a, b, drift);
}

MedianInterval CostModel::widenByDrift(MedianInterval m, std::span<const double> a,
                                       std::span<const double> b, double drift,
                                       double misfit) const {
    const double modelled = cost(b) > 0.0 ? cost(a) / cost(b) : 0.0;
    if (!(drift > 0.0) || !(modelled > 0.0) || !(m.median > 0.0)) return m;
    const auto [lowest, highest] = driftRange(a, b, drift);
    const double f = 1.0 + std::max(misfit, 0.0);
    m.low = std::min(m.low, m.median * lowest / modelled / f);
    m.high = std::max(m.high, m.median * highest / modelled * f);
    return m;
}

CostModel fitCostModel(const std::vector<std::vector<double>>& counts,
                       const std::vector<std::vector<double>>& times, std::size_t unit,
                       double confidence) {
    CostModel m;
    const std::size_t points = counts.size();
    const std::size_t kinds = points ? counts[0].size() : 0;
    const std::size_t rounds = points ? times[unit].size() : 0;
    std::vector<std::vector<double>> relative(points);  // [point][round]
    for (std::size_t p = 0; p < points; ++p) relative[p] = perSeedRatios(times[p], times[unit]);
    std::vector<double> medians(points);
    for (std::size_t p = 0; p < points; ++p) medians[p] = summarize(relative[p]).median;
    m.perKind = fitRelative(counts, medians);
    for (std::size_t r = 0; r < rounds; ++r) {
        std::vector<double> y(points);
        for (std::size_t p = 0; p < points; ++p) y[p] = relative[p][r];
        m.perRound.push_back(fitRelative(counts, y));
    }
    for (std::size_t k = 0; k < kinds; ++k) {
        std::vector<double> v;
        for (const auto& x : m.perRound) v.push_back(x[k]);
        m.perKindInterval.push_back(medianInterval(v, confidence));
    }
    for (std::size_t p = 0; p < points; ++p) {
        m.worstResidual =
            std::max(m.worstResidual, std::abs(m.cost(counts[p]) - medians[p]) / medians[p]);
    }
    return m;
}

}  // namespace engine::metrics
