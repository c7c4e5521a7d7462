#include "agaa/methods.h"

#include "agaa/aggregate/aggregate.h"
#include "agaa/fxaa/fxaa.h"
#include "agaa/reference/reference.h"
#include "agaa/sbaa/sbaa.h"
#include "agaa/simple_complex/simple_complex.h"
#include "agaa/streaming/streaming.h"
#include "agaa/temporal/temporal_aa.h"

#include <stdexcept>

namespace agaa {

const std::vector<MethodInfo>& knownMethods() {
    static const std::vector<MethodInfo> methods = {
        {"reference", "per-sample deferred shading: every covered sample lit (ground truth at the same n)",
         true, false},
        {"noaa", "one sample, one shading event per pixel", false, false},
        {"simple-complex",
         "Simple/Complex deferred MSAA (Lauritzen 2010): sample 0 lit everywhere, every sample of complex "
         "pixels",
         true,
         false,
         {"complex"}},
        {"simple-complex-naive",
         "simple-complex with per-pixel sample loops instead of per-tile packing (timing)",
         true,
         false,
         {"complex"}},
        {"fxaa", "FXAA 3.11 quality (Lottes 2009), preset 39, on the no-AA image", false, false},
        {"taa",
         "temporal AA on the no-AA path (Karis 2014): a Halton (2, 3) sub-pixel jitter per frame, the "
         "history "
         "reprojected by depth and the camera's motion and clipped to the neighbourhood in YCoCg; converges "
         "over --frames",
         false,
         false,
         {"motion"}},
        {"agaa-taa",
         "agaa (n, c) through the same temporal pass as taa, its whole sample pattern jittered each frame "
         "(the "
         "Unreal AGAA talk's combination)",
         true,
         true,
         {"motion"}},
        {"sbaa",
         "surface based anti-aliasing (Salvi and Vidimce 2012): the S most covered surfaces per pixel "
         "(--surfaces, default 4; similar planes merged) lit once each; the rest's coverage is lost",
         true,
         false,
         {},
         6,
         4},
        {"streaming",
         "streaming G-buffer compression (Kerzner and Salvi 2014): fragments merged in primitive order into "
         "at most S depth-sorted surfaces per pixel (--surfaces 1..3, default 3; --streaming-normal-angle), "
         "each lit once",
         true,
         false,
         {},
         3,
         3},
        {"agaa",
         "aggregate G-buffer anti-aliasing: n visibility samples, c aggregates lit once each "
         "(--agaa-generation picks the path; auto by default)",
         true,
         true,
         {"aggregates", "shading-rate"}},
        {"agaa-accumulate",
         "agaa with the accumulate path: visibility prepass + accumulation kernel into the AG-buffer",
         true,
         true,
         {"aggregates", "shading-rate"}},
        {"agaa-samples",
         "agaa with the samples path: one per-sample G-buffer pass, aggregated at the top of each tile",
         true,
         true,
         {"aggregates", "shading-rate"}},
    };
    return methods;
}

std::string knownMethodNames() {
    std::string s;
    for (const MethodInfo& m : knownMethods())
        s += (s.empty() ? "" : ", ") + m.name;
    return s;
}

bool isKnownMethod(const std::string& name) {
    for (const MethodInfo& m : knownMethods())
        if (m.name == name) return true;
    return false;
}

std::unique_ptr<Technique> createTechnique(const std::string& method, eng::vk::Device& device,
                                           const TechniqueContent& content, const MethodSettings& settings) {
    if (method == "reference")
        return std::make_unique<Reference>(
            device, content,
            ReferenceSettings{settings.samples, settings.effects, settings.sampleRateShading});
    if (method == "noaa")
        return std::make_unique<Reference>(device, content, ReferenceSettings{1, settings.effects}, "noaa");
    if (method == "simple-complex" || method == "simple-complex-naive") {
        SimpleComplexSettings s; // thresholds: the documented defaults (simple_complex.h)
        s.samples = settings.samples;
        s.effects = settings.effects;
        s.sampleRateShading = settings.sampleRateShading;
        if (method == "simple-complex-naive") s.schedule = SimpleComplexSchedule::Naive;
        if (!settings.debug.empty() && settings.debug != "complex")
            throw std::invalid_argument("--debug '" + settings.debug + "' is not a debug view of " + method +
                                        " (allowed: complex)");
        if (settings.debug == "complex") s.debugView = SimpleComplexDebugView::Complex;
        return std::make_unique<SimpleComplex>(device, content, s, method);
    }
    if (method == "taa" || method == "agaa-taa") {
        if (!settings.debug.empty() && settings.debug != "motion")
            throw std::invalid_argument("--debug '" + settings.debug + "' is not a debug view of " + method +
                                        " (allowed: motion)");
        TemporalSettings s;
        s.motionView = settings.debug == "motion";
        MethodSettings inner = settings;
        inner.debug.clear();
        return std::make_unique<TemporalAA>(
            device, createTechnique(method == "taa" ? "noaa" : "agaa", device, content, inner), s, method);
    }
    if (method == "fxaa") return std::make_unique<Fxaa>(device, content, FxaaSettings{}, settings.effects);
    if (method == "sbaa") {
        SbaaSettings s;
        s.samples = settings.samples;
        if (settings.surfaces) s.surfaces = settings.surfaces;
        s.effects = settings.effects;
        s.sampleRateShading = settings.sampleRateShading;
        return std::make_unique<Sbaa>(device, content, s);
    }
    if (method == "streaming") {
        StreamingSettings s;
        s.samples = settings.samples;
        if (settings.surfaces) s.surfaces = settings.surfaces;
        if (settings.streamingNormalAngle >= 0.0f) s.normalAngleDegrees = settings.streamingNormalAngle;
        s.effects = settings.effects;
        s.sampleRateShading = settings.sampleRateShading;
        return std::make_unique<StreamingCompression>(device, content, s);
    }
    if (method == "agaa" || method == "agaa-accumulate" || method == "agaa-samples") {
        AggregateSettings s;
        static_cast<AggregateChoices&>(s) = settings.agaa;
        s.samples = settings.samples;
        s.aggregates = settings.aggregates;
        s.effects = settings.effects;
        s.debugView = settings.debug == "aggregates"     ? AggregateDebugView::Aggregates
                      : settings.debug == "shading-rate" ? AggregateDebugView::ShadingRate
                                                         : AggregateDebugView::None;
        if (settings.characteristicLength >= 0.0f) s.characteristicLength = settings.characteristicLength;
        if (settings.seedThreshold >= 0.0f) s.seedThreshold = settings.seedThreshold;
        if (settings.pixelCentrePosition) s.position = AggregatePosition::PixelCentre;
        if (method != "agaa") {
            if (settings.agaa.generation != AggregateGeneration::Auto)
                throw std::invalid_argument("--agaa-generation applies to --method agaa only; " + method +
                                            " is the " + method.substr(5) + " path already");
            s.generation =
                method == "agaa-samples" ? AggregateGeneration::Samples : AggregateGeneration::Accumulate;
        }
        s.sampleRateShading = settings.sampleRateShading;
        return std::make_unique<AggregateAA>(device, content, s);
    }
    throw std::invalid_argument("--method '" + method + "' is unknown (known: " + knownMethodNames() + ")");
}

} // namespace agaa
