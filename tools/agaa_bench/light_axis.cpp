#include "light_axis.h"

#include <algorithm>
#include <cstdio>
#include <map>
#include <tuple>

namespace agaa::bench {

namespace {

const char* kSimpleComplex = "simple-complex";

std::string kText(double k) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.1f", k);
    return buf;
}

// Fills crossesAt, crossingEstimate and verdict from the row's ratios.
void findCrossing(LightAxisRow& row, const std::vector<uint32_t>& counts) {
    std::optional<size_t> first;
    for (size_t i = 0; i < counts.size(); ++i) {
        const std::optional<double>& r = row.ratioToPeer[i];
        if (!r) continue;
        if (!first) {
            first = i;
            row.fasterAtFirst = *r < 1.0;
            continue;
        }
        if ((*r < 1.0) == row.fasterAtFirst) continue;
        if (!row.beyondSpread[i]) {
            if (!row.withinSpreadAt) row.withinSpreadAt = counts[i];
            continue;
        }
        row.crossesAt = counts[i];
        // The measured K before this one with a ratio: interpolate the ratio linearly in K.
        for (size_t j = i; j-- > *first;) {
            const std::optional<double>& p = row.ratioToPeer[j];
            if (!p) continue;
            const double t = *r != *p ? (1.0 - *p) / (*r - *p) : 0.0;
            row.crossingEstimate =
                double(counts[j]) + std::clamp(t, 0.0, 1.0) * double(counts[i] - counts[j]);
            break;
        }
        break;
    }
    if (!first) {
        row.verdict = row.method == kSimpleComplex ? "the peer" : "no Simple/Complex at this n";
        return;
    }
    const std::string side = row.fasterAtFirst ? "faster" : "slower";
    const std::string other = row.fasterAtFirst ? "slower" : "faster";
    if (!row.crossesAt) {
        row.verdict = side + " than Simple/Complex at every measured K";
        if (row.withinSpreadAt)
            row.verdict += " beyond the timing spread (" + other +
                           " at K = " + std::to_string(*row.withinSpreadAt) + ", within the quartiles)";
        return;
    }
    row.verdict = other + " than Simple/Complex from K = " + std::to_string(*row.crossesAt);
    if (row.crossingEstimate) row.verdict += " (equal at K ~ " + kText(*row.crossingEstimate) + ")";
}

// The measured spread of a job: its frame, or its "<...>.lighting" pass.
std::optional<Spread> measured(const JobResult& r, LightAxisMeasure measure) {
    if (measure == LightAxisMeasure::Frame) return r.frameMs;
    for (const PassTime& p : r.passes)
        if (p.name.size() > 9 && p.name.compare(p.name.size() - 9, 9, ".lighting") == 0) return p.ms;
    return std::nullopt;
}

} // namespace

std::vector<LightAxisTable> lightAxisTables(const std::vector<JobResult>& results, LightAxisMeasure measure) {
    std::vector<std::string> scenes;
    std::map<std::string, std::vector<uint32_t>> counts;
    for (const JobResult& r : results) {
        const SceneVariant v = parseSceneVariant(r.job.scene);
        if (std::find(scenes.begin(), scenes.end(), v.base) == scenes.end()) scenes.push_back(v.base);
        std::vector<uint32_t>& c = counts[v.base];
        if (std::find(c.begin(), c.end(), v.extraLights) == c.end()) c.push_back(v.extraLights);
    }
    std::vector<LightAxisTable> tables;
    for (const std::string& scene : scenes) {
        LightAxisTable t;
        t.scene = scene;
        t.lightCounts = counts[scene];
        std::sort(t.lightCounts.begin(), t.lightCounts.end());
        if (t.lightCounts.size() < 2) continue;
        const auto column = [&](uint32_t k) {
            return size_t(std::find(t.lightCounts.begin(), t.lightCounts.end(), k) - t.lightCounts.begin());
        };
        using Key = std::tuple<std::string, uint32_t, uint32_t, uint32_t, std::string, bool>;
        std::map<Key, size_t> rowOf;
        std::map<std::pair<uint32_t, uint32_t>, Spread> peer; // (n, K) -> Simple/Complex frame ms
        for (const JobResult& r : results) {
            const SceneVariant v = parseSceneVariant(r.job.scene);
            if (v.base != scene) continue;
            const Key key{r.job.method,   r.job.samples,   r.job.aggregates,
                          r.job.surfaces, r.job.tolerance, r.job.specularAA};
            auto [it, added] = rowOf.emplace(key, t.rows.size());
            if (added) {
                LightAxisRow row;
                row.method = r.job.label();
                row.samples = r.job.samples;
                row.aggregates = r.job.aggregates;
                row.surfaces = r.job.surfaces;
                row.usesSamples = r.job.usesSamples;
                row.usesAggregates = r.job.usesAggregates;
                row.frameMs.resize(t.lightCounts.size());
                row.ratioToPeer.resize(t.lightCounts.size());
                row.beyondSpread.resize(t.lightCounts.size(), false);
                row.spreads.resize(t.lightCounts.size());
                t.rows.push_back(row);
            }
            const std::optional<Spread> m = measured(r, measure);
            if (!m) continue;
            t.rows[it->second].frameMs[column(v.extraLights)] = m->median;
            t.rows[it->second].spreads[column(v.extraLights)] = *m;
            if (r.job.method == kSimpleComplex) peer[{r.job.samples, v.extraLights}] = *m;
        }
        for (LightAxisRow& row : t.rows) {
            if (row.method != kSimpleComplex && row.usesSamples)
                for (size_t i = 0; i < t.lightCounts.size(); ++i) {
                    const auto p = peer.find({row.samples, t.lightCounts[i]});
                    if (!row.frameMs[i] || p == peer.end() || p->second.median <= 0.0) continue;
                    row.ratioToPeer[i] = *row.frameMs[i] / p->second.median;
                    const Spread& a = row.spreads[i];
                    row.beyondSpread[i] = a.q3 < p->second.q1 || p->second.q3 < a.q1;
                }
            findCrossing(row, t.lightCounts);
        }
        tables.push_back(std::move(t));
    }
    return tables;
}

} // namespace agaa::bench
