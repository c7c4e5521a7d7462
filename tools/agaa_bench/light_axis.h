#pragma once
// The light-count axis in the report (issue 15): per base scene and per method setting, the frame
// time at every extra-light count K of the sweep, its ratio to Simple/Complex at the same n and K,
// and where that ratio crosses 1 (the method turns faster or slower than Simple/Complex as lights
// grow). Methods that take no n have no Simple/Complex at their n: their row has times only.

#include "result_io.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace agaa::bench {

struct LightAxisRow {
    std::string method;
    uint32_t samples = 0, aggregates = 0;
    uint32_t surfaces = 0; // S of SBAA and streaming; 0 = none
    bool usesSamples = false, usesAggregates = false;
    std::vector<std::optional<double>> frameMs;     // per light count; nullopt: not in the run
    std::vector<std::optional<double>> ratioToPeer; // frame ms / Simple/Complex's at the same n and K
    // Per light count: the two jobs' interquartile ranges of frame time do not overlap, so which is
    // faster is beyond this run's timing spread (the machines are shared and noisy).
    std::vector<bool> beyondSpread;
    std::vector<Spread> spreads; // the job's frame-time spread per light count
    // The first measured K at which the ratio lands on the other side of 1 than at the smallest K
    // beyond the timing spread, and a linear interpolation of the ratio between that K and the one
    // before (the estimated K where the times are equal). Absent: no such crossing.
    std::optional<uint32_t> crossesAt;
    std::optional<double> crossingEstimate;
    bool fasterAtFirst = false; // ratio < 1 at the smallest measured K
    // The first K on the other side of 1 within the spread (the quartiles overlap): not a crossing.
    std::optional<uint32_t> withinSpreadAt;
    std::string verdict; // e.g. "slower than Simple/Complex from K = 16 (equal at K ~ 9.3)"
};

struct LightAxisTable {
    std::string scene;                 // the base scene
    std::vector<uint32_t> lightCounts; // ascending
    std::vector<LightAxisRow> rows;    // the order of the results
};

// What a table compares: the whole frame, or the shading pass (the pass named
// "<method>.lighting", where the light count acts).
enum class LightAxisMeasure { Frame, ShadingPass };

// One table per base scene that was measured at two or more light counts; empty when the run
// had no light-count axis. A job without the measured pass has no cell.
std::vector<LightAxisTable> lightAxisTables(const std::vector<JobResult>& results,
                                            LightAxisMeasure measure = LightAxisMeasure::Frame);

} // namespace agaa::bench
