#pragma once
// Algorithm 1 (seeds/000 section 3.3.2, DESIGN section 4.2) in double precision with rounding
// bounds, for comparing a float implementation (the GPU kernel) that may break near-ties
// differently. Shares no code with shaders/glsl/shared/clustering.h.
//
// Every distance carries an absolute bound on how far the float implementation's value of it
// can be from the double one (from bounds on its inputs' errors). A decision whose outcome could
// flip within those bounds branches: the reference explores every outcome (up to kMaxBranches) and
// the float result must equal one of them. A pixel whose branches give different metadata is a
// "tie"; one with a single possible outcome must match it exactly.
//
// Reading of the paper (as tests/agaa/test_clustering_reference.cpp): the average normal of step
// 1(b) is the plain mean of the unit normals; Equation 1 is already squared, so step 1(e) sums it;
// a seed is created only from a sample farther than t from every seed; 2(a) each sample joins
// its nearest seed.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace agaa::test::algorithm1 {

struct Sample {
    double p[3];                // view-space position divided by k
    double n[3];                // unit normal
    bool valid;                 // not sky
    double positionError = 0.0; // bound on |p_float - p| per coordinate
    double normalError = 0.0;   // bound on |n_float - n| per coordinate
};

struct Distance {
    double value, bound;
};

// Equation 1 and a bound on the float evaluation's error: the position term's error from the
// inputs' (2 |dp| e per coordinate), the normal term's (2 |1 - cos| 3 e), and 8 float roundings of
// the terms (relative 2^-24 each).
inline Distance equation1(const double* pa, const double* na, double ea, double ena, const double* pb,
                          const double* nb, double eb, double enb) {
    double d2 = 0.0, cosine = 0.0, dpSum = 0.0;
    for (int i = 0; i < 3; ++i) {
        const double dp = pa[i] - pb[i];
        d2 += dp * dp;
        dpSum += std::abs(dp);
        cosine += na[i] * nb[i];
    }
    const double o = 1.0 - cosine;
    const double value = d2 + o * o;
    const double bound = 2.0 * dpSum * (ea + eb) + 2.0 * std::abs(o) * 3.0 * (ena + enb) +
                         (ea + eb) * (ea + eb) * 3.0 + 8.0 * 0x1p-24 * (d2 + o * o + 1e-30) +
                         8.0 * 0x1p-24 * std::abs(o);
    return {value, bound};
}

struct Outcome {
    uint32_t count = 0;
    // allowed[s]: bit j set when sample s may join aggregate j (nearest within the bounds)
    std::vector<uint32_t> allowed;
};

struct Result {
    std::vector<Outcome> outcomes; // every outcome the float version may produce
    bool truncated = false;        // more than kMaxBranches: not every outcome listed
    bool exactTie = false;         // some decision was an exact tie in double
    // Whether the float version may produce different metadata (different seeds that lead to the
    // same metadata are no tie).
    bool branched() const {
        if (truncated) return true;
        for (const Outcome& o : outcomes) {
            if (o.count != outcomes[0].count || o.allowed != outcomes[0].allowed) return true;
            for (uint32_t a : o.allowed)
                if (a & (a - 1)) return true;
        }
        return false;
    }
    // Whether the float version's count and ids are one of the outcomes (sky samples not compared).
    bool admits(uint32_t count, const uint32_t* ids, const std::vector<Sample>& s) const {
        for (const Outcome& o : outcomes) {
            if (o.count != count) continue;
            bool same = true;
            for (size_t i = 0; i < s.size() && same; ++i)
                same = !s[i].valid || (ids[i] < 32 && (o.allowed[i] >> ids[i]) & 1u);
            if (same) return true;
        }
        return false;
    }
};

constexpr size_t kMaxBranches = 256;

namespace detail {

struct Context {
    const std::vector<Sample>* s;
    uint32_t c;
    double t;
    Result* result;
};

inline Distance between(const Sample& a, const Sample& b) {
    return equation1(a.p, a.n, a.positionError, a.normalError, b.p, b.n, b.positionError, b.normalError);
}

// 2(a): each valid sample's possible nearest seeds.
inline void assign(const Context& ctx, const std::vector<int>& seeds) {
    const std::vector<Sample>& s = *ctx.s;
    Outcome o;
    o.count = uint32_t(seeds.size());
    o.allowed.assign(s.size(), 0u);
    for (size_t i = 0; i < s.size(); ++i) {
        if (!s[i].valid) continue;
        std::vector<Distance> d;
        double lowestUpper = INFINITY, lowest = INFINITY;
        for (int j : seeds) {
            d.push_back(between(s[i], s[j]));
            lowestUpper = std::min(lowestUpper, d.back().value + d.back().bound);
            lowest = std::min(lowest, d.back().value);
        }
        uint32_t exactlyLowest = 0;
        for (size_t j = 0; j < d.size(); ++j) {
            if (d[j].value - d[j].bound <= lowestUpper) o.allowed[i] |= 1u << j;
            exactlyLowest += d[j].value == lowest;
        }
        ctx.result->exactTie |= exactlyLowest > 1;
    }
    if (ctx.result->outcomes.size() >= kMaxBranches) {
        ctx.result->truncated = true;
        return;
    }
    ctx.result->outcomes.push_back(std::move(o));
}

// The candidates certainly beyond t: the lowest score any of them may have (a candidate whose
// score cannot reach it is certainly beaten), and how many share the best score exactly.
struct CertainCandidates {
    double lower = -INFINITY, best = -INFINITY;
    uint32_t atBest = 0;
    void add(const Distance& score) {
        lower = std::max(lower, score.value - score.bound);
        if (score.value > best) {
            best = score.value;
            atBest = 0;
        }
        atBest += score.value == best;
    }
    bool none() const { return lower == -INFINITY; }
};

// 1(d), 1(e): the next seed, branching over every candidate that may win in float, and over
// stopping when no candidate is certainly farther than t from every seed.
inline void nextSeed(const Context& ctx, std::vector<int>& seeds) {
    const std::vector<Sample>& s = *ctx.s;
    if (seeds.size() >= ctx.c) return assign(ctx, seeds);
    struct Candidate {
        int index;
        Distance score;
        bool certain;
    };
    std::vector<Candidate> candidates;
    CertainCandidates certainOnes;
    for (int i = 0; i < int(s.size()); ++i) {
        if (!s[i].valid) continue;
        Distance nearest{INFINITY, 0.0}, sum{0.0, 0.0};
        for (int j : seeds) {
            const Distance d = between(s[i], s[j]);
            if (d.value < nearest.value) nearest = d;
            sum.value += d.value;
            sum.bound += d.bound;
        }
        if (nearest.value + nearest.bound <= ctx.t) continue; // certainly within t of a seed
        const bool certain = nearest.value - nearest.bound > ctx.t;
        const Distance score = seeds.size() == 1 ? nearest : sum;
        candidates.push_back({i, score, certain});
        if (certain) certainOnes.add(score);
    }
    ctx.result->exactTie |= certainOnes.atBest > 1;
    if (certainOnes.none()) assign(ctx, seeds); // no candidate is certainly eligible: may stop
    for (const Candidate& k : candidates) {
        if (ctx.result->truncated) return;
        if (k.score.value + k.score.bound < certainOnes.lower) continue; // certainly beaten
        seeds.push_back(k.index);
        nextSeed(ctx, seeds);
        seeds.pop_back();
    }
}

// c = 1's layer split (DESIGN section 4.2): how far apart two samples' surfaces lie, the mean
// of the squared distances of each to the other's tangent plane, and a bound on the float
// evaluation's error (the inputs' errors through both dot products, 6 float roundings).
inline Distance layerDistance(const double* pa, const double* na, double ea, double ena, const double* pb,
                              const double* nb, double eb, double enb) {
    double da = 0.0, db = 0.0, errA = 0.0, errB = 0.0, dpSum = 0.0;
    for (int i = 0; i < 3; ++i) {
        const double dp = pa[i] - pb[i];
        da += dp * na[i];
        db += dp * nb[i];
        dpSum += std::abs(dp);
        errA += std::abs(na[i]) * (ea + eb) + std::abs(dp) * ena;
        errB += std::abs(nb[i]) * (ea + eb) + std::abs(dp) * enb;
    }
    errA += 4.0 * 0x1p-24 * (dpSum + 1e-30);
    errB += 4.0 * 0x1p-24 * (dpSum + 1e-30);
    const double value = 0.5 * (da * da + db * db);
    const double bound = std::abs(da) * errA + std::abs(db) * errB + 0.5 * (errA * errA + errB * errB) +
                         6.0 * 0x1p-24 * (value + 1e-30);
    return {value, bound};
}

inline Distance layerBetween(const Sample& a, const Sample& b) {
    return layerDistance(a.p, a.n, a.positionError, a.normalError, b.p, b.n, b.positionError, b.normalError);
}

// The layers from seeds 0 and (if any) 1: every sample to its nearer seed, the larger layer on
// (bit 0 of allowed), the other off (bit 1); equal layers keep seed 0's on. Samples within
// rounding of both seeds, and counts that such samples could tip, give every outcome.
inline void assignLayers(const Context& ctx, int seed0, int seed1) {
    const std::vector<Sample>& s = *ctx.s;
    std::vector<uint32_t> may(s.size(), 0u); // bit j: the sample may join seed j
    uint32_t certain0 = 0, certain1 = 0, either = 0;
    for (size_t i = 0; i < s.size(); ++i) {
        if (!s[i].valid) continue;
        if (seed1 < 0) {
            may[i] = 1u;
            ++certain0;
            continue;
        }
        const Distance d0 = layerBetween(s[i], s[seed0]), d1 = layerBetween(s[i], s[seed1]);
        ctx.result->exactTie |= d0.value == d1.value;
        // The float version joins seed 1 only when strictly nearer.
        if (d1.value + d1.bound < d0.value - d0.bound)
            may[i] = 2u;
        else if (d0.value + d0.bound <= d1.value - d1.bound)
            may[i] = 1u;
        else
            may[i] = 3u;
        certain0 += may[i] == 1u;
        certain1 += may[i] == 2u;
        either += may[i] == 3u;
    }
    // Whether the layer of seed 1 may be (strictly) the larger, and whether seed 0's may.
    const bool swapPossible = certain1 + either > certain0;
    const bool keepPossible = certain0 + either >= certain1;
    for (int swap = 0; swap < 2; ++swap) {
        if ((swap && !swapPossible) || (!swap && !keepPossible)) continue;
        Outcome o;
        o.count = 1;
        o.allowed.assign(s.size(), 0u);
        for (size_t i = 0; i < s.size(); ++i) {
            if (!s[i].valid) continue;
            const uint32_t on = swap ? 2u : 1u; // the seed whose layer is the aggregate
            o.allowed[i] = ((may[i] & on) ? 1u : 0u) | ((may[i] & ~on & 3u) ? 2u : 0u);
        }
        if (ctx.result->outcomes.size() >= kMaxBranches) {
            ctx.result->truncated = true;
            return;
        }
        ctx.result->outcomes.push_back(std::move(o));
    }
}

// Seed 1 of the layer split: the sample farthest from seed 0 beyond t, branching as nextSeed does.
inline void layerSeed(const Context& ctx, int seed0) {
    const std::vector<Sample>& s = *ctx.s;
    std::vector<std::pair<int, Distance>> candidates;
    CertainCandidates certainOnes;
    for (int i = 0; i < int(s.size()); ++i) {
        if (!s[i].valid) continue;
        const Distance d = layerBetween(s[i], s[seed0]);
        if (d.value + d.bound <= ctx.t) continue; // certainly on seed 0's layer
        candidates.push_back({i, d});
        if (d.value - d.bound > ctx.t) certainOnes.add(d);
    }
    ctx.result->exactTie |= certainOnes.atBest > 1;
    if (certainOnes.none()) assignLayers(ctx, seed0, -1); // may find no second layer
    for (const auto& [index, d] : candidates) {
        if (ctx.result->truncated) return;
        if (d.value + d.bound < certainOnes.lower) continue;
        assignLayers(ctx, seed0, index);
    }
}

// 1(c) the first seed: the samples farthest from the mean, every candidate within the bounds of
// the best (distanceToMean(i): a sample's distance to the mean, with its bound).
template <class DistanceToMean>
std::vector<int> firstSeeds(const std::vector<Sample>& s, DistanceToMean distanceToMean, Result& result) {
    std::vector<Distance> d(s.size(), Distance{-1.0, 0.0});
    double lower = -INFINITY, best = -INFINITY;
    for (size_t i = 0; i < s.size(); ++i) {
        if (!s[i].valid) continue;
        d[i] = distanceToMean(s[i]);
        lower = std::max(lower, d[i].value - d[i].bound);
        best = std::max(best, d[i].value);
    }
    uint32_t atBest = 0;
    for (size_t i = 0; i < s.size(); ++i)
        atBest += s[i].valid && d[i].value == best;
    result.exactTie |= atBest > 1;
    std::vector<int> out;
    for (size_t i = 0; i < s.size(); ++i)
        if (s[i].valid && d[i].value + d[i].bound >= lower) out.push_back(int(i));
    return out;
}

} // namespace detail

// c = 1 (DESIGN section 4.2): one aggregate, on the larger of the pixel's two layers. Seeds as
// Algorithm 1's first two, on the layer distance: seed 0 the sample farthest from the mean, seed 1
// the one farthest from seed 0 if beyond t; the other layer's samples keep only their coverage.
inline Result layers(const std::vector<Sample>& s, double t, const double* mp, const double* mn,
                     double meanErrP, double meanErrN) {
    Result result;
    detail::Context ctx{&s, 1, t, &result};
    const auto toMean = [&](const Sample& x) {
        return detail::layerDistance(x.p, x.n, x.positionError, x.normalError, mp, mn, meanErrP, meanErrN);
    };
    for (int seed0 : detail::firstSeeds(s, toMean, result)) {
        if (result.truncated) break;
        detail::layerSeed(ctx, seed0);
    }
    return result;
}

// Algorithm 1 on one pixel's samples, c aggregates at most, seed threshold t.
inline Result cluster(const std::vector<Sample>& s, uint32_t c, double t) {
    Result result;
    detail::Context ctx{&s, c, t, &result};
    // 1(b) mean position and normal of the valid samples; the float sums' errors: one rounding of
    // the running sum per sample (relative 2^-24 of the largest magnitude) on top of the inputs'.
    double mp[3] = {0, 0, 0}, mn[3] = {0, 0, 0}, scaleP = 0.0, errP = 0.0, errN = 0.0;
    int visible = 0;
    for (const Sample& x : s) {
        if (!x.valid) continue;
        ++visible;
        for (int i = 0; i < 3; ++i) {
            mp[i] += x.p[i];
            mn[i] += x.n[i];
            scaleP = std::max(scaleP, std::abs(x.p[i]));
        }
        errP = std::max(errP, x.positionError);
        errN = std::max(errN, x.normalError);
    }
    if (visible == 0) {
        result.outcomes.push_back({0, std::vector<uint32_t>(s.size(), 1u)});
        return result;
    }
    for (int i = 0; i < 3; ++i) {
        mp[i] /= visible;
        mn[i] /= visible;
    }
    const double meanErrP = errP + double(visible + 1) * 0x1p-24 * scaleP;
    const double meanErrN = errN + double(visible + 1) * 0x1p-24;
    if (c == 1) return layers(s, t, mp, mn, meanErrP, meanErrN);
    // 1(c) the first seed: farthest from the mean (every candidate within the bounds of the best).
    const auto toMean = [&](const Sample& x) {
        return equation1(x.p, x.n, x.positionError, x.normalError, mp, mn, meanErrP, meanErrN);
    };
    std::vector<int> seeds;
    for (int seed0 : detail::firstSeeds(s, toMean, result)) {
        if (result.truncated) break;
        seeds = {seed0};
        detail::nextSeed(ctx, seeds);
    }
    return result;
}

} // namespace agaa::test::algorithm1
