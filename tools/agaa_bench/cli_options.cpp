#include "cli_options.h"

#include "agaa/method_settings.h"
#include "agaa/methods.h"
#include "engine/scene/extra_lights.h"
#include "engine/scene/scenegen.h"
#include "tools/harness/converged_truth.h"

#include <algorithm>
#include <charconv>
#include <optional>
#include <sstream>

namespace agaa::bench {

namespace {

// One value of an axis (n, c or S), checked by its method setting (agaa/method_settings.h).
MethodSettings axisValue(const char* name, const std::string& value) {
    MethodSettings s;
    try {
        setMethodOption(s, *findMethodOption(name), value);
    } catch (const std::invalid_argument& e) {
        throw BadArgument(e.what());
    }
    return s;
}

// The default sweep: small enough for about 5 minutes on 2 shared cores with validation off.
constexpr uint32_t kDefaultWidth = 160, kDefaultHeight = 90;
const std::vector<uint32_t> kDefaultSamples = {8, 16, 32};
const std::vector<uint32_t> kDefaultAggregates = {1, 2};
// --full: the paper's settings (section 5, table 1).
constexpr uint32_t kFullWidth = 1280, kFullHeight = 720;
const std::vector<uint32_t> kFullSamples = {8, 32};
const std::vector<uint32_t> kFullAggregates = {1, 2, 3, 4};

std::vector<std::string> splitList(const std::string& flag, const std::string& value) {
    std::vector<std::string> items;
    std::stringstream s(value);
    for (std::string item; std::getline(s, item, ',');) {
        if (item.empty()) throw BadArgument(flag + " '" + value + "' has an empty item (use a,b,c)");
        items.push_back(item);
    }
    if (items.empty()) throw BadArgument(flag + " needs at least one value");
    return items;
}

uint32_t parseUint(const std::string& flag, const std::string& value, uint32_t lo, uint32_t hi) {
    uint32_t v = 0;
    auto [ptr, ec] = std::from_chars(value.data(), value.data() + value.size(), v);
    if (ec != std::errc() || ptr != value.data() + value.size() || value.empty() || v < lo || v > hi)
        throw BadArgument(flag + " '" + value + "' is not an integer in " + std::to_string(lo) + ".." +
                          std::to_string(hi));
    return v;
}

std::string joined(const std::vector<std::string>& v) {
    std::string s;
    for (const std::string& x : v)
        s += (s.empty() ? "" : ", ") + x;
    return s;
}

} // namespace

std::string usage() {
    return "usage: agaa-bench --out DIR [--scenes a,b] [--methods a,b] [--samples 8,32] [--aggregates 1,2]\n"
           "                  [--surfaces 1,2,3] [--tolerances never,30,0] [--specular-aa off,on] [--size "
           "WxH] "
           "[--frames K] "
           "[--warmup K] [--temporal K] [--temporal-path orbit|truck] "
           "[--full] [--job I/N]\n"
           "                  [--truth-supersampling K] [--truth-cache DIR]\n"
           "                  [--extra-lights 0,4,16,64] [--validate] [--help] [--SETTING VALUE...]\n"
           "       agaa-bench --out DIR --merge DIR1 DIR2 ...\n"
           "\n"
           "Renders every method and setting on every scene, measures GPU time per pass, memory, and error\n"
           "against the reference at the same n and against a converged truth (the reference at n=32 with\n"
           "sample-rate shading, supersampled K x K; its own error estimate is printed), and\n"
           "writes DIR/jobs/<scene>__<method>__n<N>__c<C>.json, DIR/results.json, DIR/results.csv,\n"
           "DIR/report.html and DIR/images/. Error metrics are on the tone-mapped display image, "
           "sRGB-encoded.\n"
           "\n"
           "  --out DIR         output directory (required)\n"
           "  --scenes a,b      built-in scenes (default: " +
           joined(defaultSweepScenes()) +
           ")\n"
           "  --methods a,b     methods (default: all known)\n"
           "  --samples 8,32    n for methods that take it: 1, 4, 8, 16, 32 (default 8,16,32)\n"
           "  --aggregates 1,2  c for methods that take it: 1..4 (default 1,2)\n"
           "  --surfaces 1,3    S for the methods that take it, 1..6, each method keeping the values in\n"
           "                    its range (sbaa 1..6, streaming 1..3); default: each method's own (4, 3)\n"
           "  --tolerances never,30,0  AGAA's shading-rate axis (--agaa-tolerance: auto, the default; "
           "never,\n"
           "                    the paper's AGAA; or T >= 0, 0 the reference) for agaa and agaa-samples;\n"
           "                    jobs other than auto are named ...__t<T>\n"
           "  --specular-aa off,on  geometric specular AA (--curvature-roughness) as an axis: every job\n"
           "                    once per value, those with it named ...__saa and labelled \"+ specular AA\"\n"
           "  --size WxH        image size, 1..8192 each (default 160x90)\n"
           "  --frames K        timed frames per job, 1..1000 (default 3); times are medians with min/max\n"
           "  --warmup K        untimed frames first, 0..1000 (default 1)\n"
           "  --temporal K      frames on the camera path for temporal stability, 0 (off) or 2..64\n"
           "                    (default 5, 0.5 degree steps, rendered at most 320 pixels wide), each frame\n"
           "                    against its own truth: flicker and the path's mean error (what a user who\n"
           "                    moves sees; a temporal method carries its history along it)\n"
           "  --temporal-path orbit|truck  the path: an orbit about the scene's centre (default), or the\n"
           "                    camera trucked sideways by 1 % of the bounds' diagonal a frame (parallax,\n"
           "                    disocclusion)\n"
           "  --full            the paper's settings: 1280x720, n = 8 and 32, c = 1..4, all scenes\n"
           "                    (flags given explicitly still win)\n"
           "  --job I/N         run only jobs I, I+N, I+2N, ... of the plan (split a sweep; merge with "
           "--merge)\n"
           "  --merge DIR...    merge the jobs of several output directories into --out, without rendering\n"
           "  --SETTING VALUE   a method setting of agaa-render's (agaa-render --help), applied to every\n"
           "                    job whose method reads it, the same-n reference's too (the converged truth\n"
           "                    is always the reference at n = 32 with sample-rate shading), e.g.\n"
           "                    --agaa-generation accumulate (the methods agaa-accumulate and agaa-samples\n"
           "                    sweep both paths side by side) or --sample-rate-shading on\n"
           "  --truth-supersampling K  the truth's K x K sub-pixel tiles at n = 32, 1..16 (default 4: 512\n"
           "                    samples a pixel); an error difference below the truth's own error\n"
           "                    estimate is reported as undecided\n"
           "  --truth-cache DIR  where truths are kept between runs (default $AGAA_TRUTH_CACHE, else\n"
           "                    DIR/truth-cache)\n"
           "  --extra-lights K,...  the light-count axis: every scene once per K, 0..1000, with K generated\n"
           "                    point lights (a Halton sequence in the bounds, each lighting its\n"
           "                    neighbourhood like the key light; agaa-render --help); scene variants are\n"
           "                    named <scene>+l<K>, and the report tables where each method crosses\n"
           "                    Simple/Complex in frame time (default 0: the scenes' own lights only)\n"
           "  --validate        Khronos validation layer on; a validation error makes the exit status 1\n"
           "\n"
           "exit status: 0 done; 1 a job failed or validation errors; 2 bad arguments or missing Chart.js;\n"
           "3 the device lacks something every job needs.\n";
}

BenchOptions parseOptions(int argc, char** argv) {
    BenchOptions o;
    for (int i = 0; i < argc; ++i)
        o.command += (i ? " " : "") + std::string(argv[i]);
    std::optional<std::vector<std::string>> scenes, methods;
    std::optional<std::vector<uint32_t>> samples, aggregates;
    std::optional<uint32_t> width, height;
    bool full = false, merge = false, sliced = false;
    SweepSettings& s = o.sweep;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto value = [&]() -> std::string {
            if (i + 1 >= argc) throw BadArgument(a + " needs a value");
            return argv[++i];
        };
        const MethodOption* setting = a.rfind("--", 0) == 0 ? findMethodOption(a.substr(2)) : nullptr;
        if (setting && setting->name != "samples" && setting->name != "aggregates" &&
            setting->name != "surfaces") {
            try {
                setMethodOption(s.methodSettings, *setting, value());
            } catch (const std::invalid_argument& e) {
                throw BadArgument(e.what());
            }
            s.givenSettings.push_back(setting->name);
        } else if (a == "--help" || a == "-h")
            o.help = true;
        else if (a == "--out")
            o.out = value();
        else if (a == "--scenes") {
            scenes = splitList(a, value());
            const std::vector<std::string> known = eng::scene::sceneKinds();
            for (const std::string& sc : *scenes) {
                if (std::find(known.begin(), known.end(), sc) != known.end() || realScenePath(sc)) continue;
                std::string real;
                for (const RealScene& r : realScenes())
                    real += (real.empty() ? "" : ", ") + r.name + " (" +
                            (sharedScenesDir() / r.file).string() + ")";
                throw BadArgument("--scenes: '" + sc + "' is not a built-in scene (known: " + joined(known) +
                                  ") nor a real scene whose file exists (" + real + ")");
            }
        } else if (a == "--methods") {
            methods = splitList(a, value());
            for (const std::string& m : *methods)
                if (!isKnownMethod(m))
                    throw BadArgument("--methods: '" + m + "' is unknown (known: " + knownMethodNames() +
                                      ")");
        } else if (a == "--samples") {
            samples.emplace();
            for (const std::string& v : splitList(a, value()))
                samples->push_back(axisValue("samples", v).samples);
        } else if (a == "--extra-lights") {
            s.extraLights.clear();
            for (const std::string& v : splitList(a, value()))
                s.extraLights.push_back(parseUint(a, v, 0, eng::scene::kMaxExtraLights));
        } else if (a == "--surfaces") {
            s.surfaces.clear();
            for (const std::string& v : splitList(a, value()))
                s.surfaces.push_back(axisValue("surfaces", v).surfaces);
        } else if (a == "--specular-aa") {
            s.specularAA.clear();
            for (const std::string& v : splitList(a, value())) {
                if (v != "off" && v != "on")
                    throw BadArgument("--specular-aa: '" + v + "' is not one of: off, on");
                if (std::find(s.specularAA.begin(), s.specularAA.end(), v == "on") == s.specularAA.end())
                    s.specularAA.push_back(v == "on");
            }
        } else if (a == "--tolerances") {
            s.tolerances.clear();
            const MethodOption& tolerance = *findMethodOption("agaa-tolerance");
            for (const std::string& v : splitList(a, value())) {
                try {
                    s.tolerances.push_back(tolerance.get(axisValue("agaa-tolerance", v))); // its own text
                } catch (const BadArgument& e) {
                    throw BadArgument("--tolerances: " + std::string(e.what())); // the flag given
                }
            }
        } else if (a == "--aggregates") {
            aggregates.emplace();
            for (const std::string& v : splitList(a, value()))
                aggregates->push_back(axisValue("aggregates", v).aggregates);
        } else if (a == "--size") {
            const std::string v = value();
            const size_t x = v.find('x');
            if (x == std::string::npos) throw BadArgument("--size '" + v + "' is not WxH (e.g. 160x90)");
            width = parseUint("--size width", v.substr(0, x), 1, 8192);
            height = parseUint("--size height", v.substr(x + 1), 1, 8192);
        } else if (a == "--frames")
            s.timedFrames = parseUint(a, value(), 1, 1000);
        else if (a == "--warmup")
            s.warmupFrames = parseUint(a, value(), 0, 1000);
        else if (a == "--temporal") {
            const std::string v = value();
            s.temporalFrames = parseUint(a, v, 0, 64);
            if (s.temporalFrames == 1)
                throw BadArgument("--temporal '1': a path needs 0 (off) or 2..64 frames");
        } else if (a == "--temporal-path") {
            const std::string v = value();
            if (v != "orbit" && v != "truck")
                throw BadArgument("--temporal-path: '" + v + "' is not one of: orbit, truck");
            s.temporalPath =
                v == "truck" ? SweepSettings::TemporalPath::Truck : SweepSettings::TemporalPath::Orbit;
        } else if (a == "--truth-supersampling")
            s.truthSupersampling = parseUint(a, value(), 1, agaa::kMaxTruthSupersampling);
        else if (a == "--truth-cache")
            s.truthCache = value();
        else if (a == "--full")
            full = true;
        else if (a == "--job") {
            try {
                o.slice = parseJobSlice(value());
            } catch (const std::invalid_argument& e) {
                throw BadArgument(e.what());
            }
            sliced = true;
        } else if (a == "--merge") {
            merge = true;
            while (i + 1 < argc && std::string(argv[i + 1]).rfind("--", 0) != 0)
                o.mergeDirs.emplace_back(argv[++i]);
            if (o.mergeDirs.empty()) throw BadArgument("--merge needs at least one directory");
        } else if (a == "--validate")
            s.validate = true;
        else
            throw BadArgument("unknown argument '" + a + "' (see --help)");
    }
    if (o.help) return o;
    if (o.out.empty()) throw BadArgument("--out DIR is required (see --help)");
    if (merge && sliced) throw BadArgument("--job and --merge do not go together: --merge renders nothing");
    if (s.truthCache.empty()) s.truthCache = agaa::truthCacheDir(o.out / "truth-cache");

    s.scenes = scenes ? *scenes : full ? eng::scene::sceneKinds() : defaultSweepScenes();
    if (methods)
        s.methods = *methods;
    else
        for (const MethodInfo& m : knownMethods())
            s.methods.push_back(m.name);
    s.samples = samples ? *samples : full ? kFullSamples : kDefaultSamples;
    s.aggregates = aggregates ? *aggregates : full ? kFullAggregates : kDefaultAggregates;
    s.width = width ? *width : full ? kFullWidth : kDefaultWidth;
    s.height = height ? *height : full ? kFullHeight : kDefaultHeight;
    return o;
}

} // namespace agaa::bench
