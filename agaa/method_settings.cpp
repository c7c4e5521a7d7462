#include "agaa/method_settings.h"

#include "agaa/aggregate/agaa_constants.h"
#include "engine/frame/sample_pattern.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>

namespace agaa {

namespace {

using Kind = MethodOption::Kind;

// The word `get` gives, and `set` takes, for "the method's own default" where MethodSettings holds
// a sentinel (0 surfaces, a negative angle, length or threshold).
constexpr const char* kDefault = "default";

// The words of an enum's NamedValue table, in its order.
template <typename T, size_t N> std::vector<std::string> words(const NamedValue<T> (&table)[N]) {
    std::vector<std::string> out;
    for (const NamedValue<T>& entry : table)
        out.push_back(entry.name);
    return out;
}

std::string joined(const std::vector<std::string>& values, const char* separator) {
    std::string out;
    for (const std::string& v : values)
        out += (out.empty() ? "" : separator) + v;
    return out;
}

// A number as the key and `get` print it: shortest round-trip form.
std::string numberText(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.9g", v);
    return text;
}

MethodOption choice(std::string name, std::vector<std::string> choices, std::string defaultText,
                    std::string methods, std::string doc,
                    std::function<void(MethodSettings&, const std::string&)> set,
                    std::function<std::string(const MethodSettings&)> get) {
    MethodOption o;
    o.name = std::move(name);
    o.syntax = joined(choices, "|");
    o.kind = Kind::Choice;
    o.choices = std::move(choices);
    o.defaultText = std::move(defaultText);
    o.methods = std::move(methods);
    o.doc = std::move(doc);
    o.set = std::move(set);
    o.get = std::move(get);
    return o;
}

// One of AGAA's choices (MethodSettings::agaa), an enum: its words are the enum's NamedValue table,
// its default the AggregateChoices default's word, and the value is parsed once, here.
template <typename T, size_t N>
MethodOption enumChoice(std::string name, const NamedValue<T> (&table)[N], T AggregateChoices::*field,
                        std::string methods, std::string doc) {
    const std::string flag = "--" + name;
    return choice(
        std::move(name), words(table), nameOf(AggregateChoices{}.*field, table), std::move(methods),
        std::move(doc),
        [&table, field, flag](MethodSettings& s, const std::string& v) {
            s.agaa.*field = namedValue(flag.c_str(), v, table);
        },
        [&table, field](const MethodSettings& s) { return std::string(nameOf(s.agaa.*field, table)); });
}

MethodOption ranged(Kind kind, std::string name, std::string syntax, double lo, double hi,
                    std::string defaultText, std::string methods, std::string doc,
                    std::function<void(MethodSettings&, const std::string&)> set,
                    std::function<std::string(const MethodSettings&)> get) {
    MethodOption o;
    o.name = std::move(name);
    o.syntax = std::move(syntax);
    o.kind = kind;
    o.lo = lo;
    o.hi = hi;
    o.defaultText = std::move(defaultText);
    o.methods = std::move(methods);
    o.doc = std::move(doc);
    o.set = std::move(set);
    o.get = std::move(get);
    return o;
}

// on|off <-> bool
std::string onOff(bool v) {
    return v ? "on" : "off";
}

std::vector<MethodOption> declareOptions() {
    const auto count = [](const std::string& v) { return uint32_t(std::stoul(v)); };
    const auto number = [](const std::string& v) { return std::stof(v); };
    // A negative float means "the method's documented default" in MethodSettings.
    const auto orDefault = [](float v) { return v < 0.0f ? std::string(kDefault) : numberText(v); };
    std::vector<MethodOption> o;
    std::vector<std::string> sampleCounts;
    for (uint32_t n = 1; n <= 32; ++n)
        if (eng::frame::isSupportedSampleCount(n)) sampleCounts.push_back(std::to_string(n));
    o.push_back(choice(
        "samples", sampleCounts, "8", "all",
        "visibility samples per pixel: 1 and 4 native, 8, 16 and 32 emulated by layered 4x",
        [=](MethodSettings& s, const std::string& v) { s.samples = count(v); },
        [](const MethodSettings& s) { return std::to_string(s.samples); }));
    o.push_back(ranged(
        Kind::Count, "aggregates", "C", 1, 4, "2", "agaa*", "aggregates per pixel",
        [=](MethodSettings& s, const std::string& v) { s.aggregates = count(v); },
        [](const MethodSettings& s) { return std::to_string(s.aggregates); }));
    o.push_back(ranged(
        Kind::Count, "surfaces", "S", 1, 6, "sbaa 4, streaming 3", "sbaa, streaming",
        "surfaces kept per pixel: sbaa 1..6, streaming 1..3",
        [=](MethodSettings& s, const std::string& v) { s.surfaces = v == kDefault ? 0 : count(v); },
        [](const MethodSettings& s) {
            return s.surfaces ? std::to_string(s.surfaces) : std::string(kDefault);
        }));
    o.push_back(ranged(
        Kind::Number, "streaming-normal-angle", "DEG", 1e-3, 90.0, "45, the paper's pi/4", "streaming",
        "the merge threshold on normals in degrees (the authors' code uses cos = 0.785, about 38.2)",
        [=](MethodSettings& s, const std::string& v) {
            s.streamingNormalAngle = v == kDefault ? -1.0f : number(v);
        },
        [=](const MethodSettings& s) { return orDefault(s.streamingNormalAngle); }));
    o.push_back(ranged(
        Kind::Number, "characteristic-length", "K", 1e-6, 1e6, "0.1", "agaa*",
        "clustering (Equation 1): the characteristic length k in metres",
        [=](MethodSettings& s, const std::string& v) {
            s.characteristicLength = v == kDefault ? -1.0f : number(v);
        },
        [=](const MethodSettings& s) { return orDefault(s.characteristicLength); }));
    o.push_back(ranged(
        Kind::Number, "seed-threshold", "T", 0.0, 1e6, "0.05", "agaa*",
        "clustering (Equation 1): the seed threshold t",
        [=](MethodSettings& s, const std::string& v) { s.seedThreshold = v == kDefault ? -1.0f : number(v); },
        [=](const MethodSettings& s) { return orDefault(s.seedThreshold); }));
    o.push_back(choice(
        "agaa-position", words(kAggregatePositionNames), "mean", "agaa*",
        "the shading point: the mean of the aggregate's samples, or UE4's mean depth on the pixel-centre ray",
        [](MethodSettings& s, const std::string& v) {
            s.pixelCentrePosition =
                namedValue("--agaa-position", v, kAggregatePositionNames) == AggregatePosition::PixelCentre;
        },
        [](const MethodSettings& s) {
            return std::string(
                nameOf(s.pixelCentrePosition ? AggregatePosition::PixelCentre : AggregatePosition::SampleMean,
                       kAggregatePositionNames));
        }));
    o.push_back(enumChoice(
        "agaa-ndf", kAggregateNdfNames, &AggregateChoices::ndf, "agaa*",
        "the normal distribution per aggregate: anisotropic SGGX with the two-point tone-mapped resolve, "
        "or the paper's isotropic Toksvig; auto: SGGX when glossy metals that are not near mirrors "
        "(roughness 0.1 to 0.4) are at least half of the drawn materials, else Toksvig"));
    o.push_back(enumChoice(
        "agaa-lighting", kAggregateShadingNames, &AggregateChoices::shading, "agaa*",
        "the lighting schedule: a tile's further aggregates packed into a shared-memory list (compact), "
        "or each pixel shading its own (registers); auto: compact for c >= 2, registers at c = 1"));
    o.push_back(enumChoice(
        "agaa-routing", kAggregateRoutingNames, &AggregateChoices::routing, "agaa*",
        "generation: each visible sample feeds its own aggregate, or the whole fragment its first visible "
        "sample's (Algorithm 2)"));
    o.push_back(enumChoice(
        "agaa-atomics", kAggregateAtomicsNames, &AggregateChoices::atomics, "agaa*",
        "generation atomics: 64-bit pairs of words where the device has shaderBufferInt64Atomics (auto), "
        "or 32-bit words"));
    o.push_back(enumChoice(
        "agaa-subgroup-reduce", kSubgroupReductionNames, &AggregateChoices::subgroupReduction, "agaa*",
        "generation: sum the atomics of fragments that hit one pixel across the subgroup first; auto: on "
        "for GPUs, off on CPU devices"));
    o.push_back(enumChoice(
        "agaa-distance", kAggregateDistanceNames, &AggregateChoices::distance, "agaa*",
        "clustering: Equation 1, or the samples' distance to each other's tangent plane (a flat surface "
        "stays one aggregate)"));
    {
        MethodOption t = ranged(
            Kind::Number, "agaa-tolerance", "auto|never|T", 0.0, 1e7, "auto",
            "agaa, agaa-samples, agaa-accumulate",
            "the error-driven shading rate: an aggregate whose normal spread, against its sharpest member's "
            "lobe, reaches T has its samples shaded one by one as the reference shades them, and the whole "
            "pixel is where every aggregate of it does (0: every pixel, the reference's image; "
            "docs/decisions/shading-rate-estimate.md). auto: " +
                numberText(kDefaultTolerance) +
                " on the samples path, never on the accumulate path (where a tolerance keeps 12 bytes of "
                "material per sample)",
            [=](MethodSettings& s, const std::string& v) {
                s.agaa.tolerance = v == "auto" ? kToleranceAuto : v == "never" ? kToleranceNever : number(v);
            },
            [](const MethodSettings& s) {
                return s.agaa.tolerance == kToleranceAuto ? std::string("auto")
                       : s.agaa.tolerance < 0.0f          ? std::string("never")
                                                          : numberText(s.agaa.tolerance);
            });
        t.words = {"auto", "never"};
        o.push_back(std::move(t));
    }
    {
        MethodOption l = ranged(
            Kind::Number, "agaa-alias-limit", "none|L", 1.0, 1e7, numberText(kDefaultAliasLimit),
            "agaa, agaa-samples",
            "with a tolerance above 0, a pixel whose estimate reaches L keeps its aggregates: its lobe is so "
            "much narrower than its normals' spread that n samples alias the highlight the aggregate's lobe "
            "integrates (measured at n = 8 in docs/decisions/shading-rate-estimate.md)",
            [=](MethodSettings& s, const std::string& v) {
                s.agaa.aliasLimit = v == "none" ? kAliasLimitNone : number(v);
            },
            [](const MethodSettings& s) {
                return std::isinf(s.agaa.aliasLimit) ? std::string("none") : numberText(s.agaa.aliasLimit);
            });
        l.words = {"none"};
        o.push_back(std::move(l));
    }
    o.push_back(enumChoice(
        "agaa-generation", kAggregateGenerationNames, &AggregateChoices::generation, "agaa",
        "the generation path: the accumulation kernel after a visibility prepass, or one per-sample "
        "G-buffer pass aggregated at the top of each lighting tile (UE4); coverage routing needs mixed "
        "samples and the sample-mask override and is not built (exit 3); auto: samples for n <= 16, else "
        "accumulate"));
    o.push_back(choice(
        "sample-rate-shading", {"on", "off"}, "off", "reference, simple-complex*, sbaa, streaming, agaa*",
        "the per-sample G-buffer filled at sample rate: materials and normal maps supersampled",
        [](MethodSettings& s, const std::string& v) { s.sampleRateShading = v == "on"; },
        [](const MethodSettings& s) { return onOff(s.sampleRateShading); }));
    o.push_back(choice(
        "curvature-roughness", {"on", "off"}, "off", "all",
        "geometric specular AA in every method's material evaluation: GGX alpha^2 widened by the geometric "
        "normal's screen-space variance (Tokuyoshi and Kaplanyan 2019; max footprint 0.3, boost 2.0, the "
        "UE4 AGAA talk's); the converged truth never applies it",
        [](MethodSettings& s, const std::string& v) { s.effects.curvatureRoughness.enabled = v == "on"; },
        [](const MethodSettings& s) { return onOff(s.effects.curvatureRoughness.enabled); }));
    o.push_back(choice(
        "effects", {"scene", "all"}, "scene", "all",
        "passes and shader variants from the scene's features, or every effect forced on (shadows, "
        "alpha-to-coverage, emissive, normal maps, light culling)",
        [](MethodSettings& s, const std::string& v) { s.effects.forceAll = v == "all"; },
        [](const MethodSettings& s) { return std::string(s.effects.forceAll ? "all" : "scene"); }));
    o.push_back(ranged(
        Kind::Count, "shadow-taps", "N", 1, 8, "4", "agaa*", "shadow taps inside each aggregate's footprint",
        [=](MethodSettings& s, const std::string& v) { s.effects.shadowTaps = count(v); },
        [](const MethodSettings& s) { return std::to_string(s.effects.shadowTaps); }));
    o.push_back(choice(
        "shadow-footprint", words(kShadowFootprintNames), "adaptive", "agaa*",
        "shadow taps along the aggregate's depth variance (statistics), at its own sample positions "
        "(samples), or along the variance and, where those taps disagree, at every one of its samples "
        "(adaptive; at n <= 5 + taps at every sample outright)",
        [](MethodSettings& s, const std::string& v) {
            s.effects.shadowFootprint = namedValue("--shadow-footprint", v, kShadowFootprintNames);
        },
        [](const MethodSettings& s) {
            return std::string(nameOf(s.effects.shadowFootprint, kShadowFootprintNames));
        }));
    o.push_back(ranged(
        Kind::Count, "shadow-map-size", "N", 64, 4096, "1024", "all", "texels per side of each shadow map",
        [=](MethodSettings& s, const std::string& v) { s.effects.shadowMapSize = count(v); },
        [](const MethodSettings& s) { return std::to_string(s.effects.shadowMapSize); }));
    MethodOption debug = ranged(
        Kind::Text, "debug", "VIEW", 0, 0, "none", "agaa*, simple-complex*, taa",
        "a method's debug view instead of the lit frame (agaa: aggregates; simple-complex: complex; taa: "
        "motion, "
        "the reprojected pixel position)",
        [](MethodSettings& s, const std::string& v) { s.debug = v; },
        [](const MethodSettings& s) { return s.debug; });
    o.push_back(debug);
    return o;
}

// `text` wrapped at `width` columns; lines after the first start with `indent` spaces.
std::string wrapped(const std::string& text, size_t indent, size_t width, size_t firstColumn) {
    std::istringstream words(text);
    std::string out, word;
    size_t column = firstColumn;
    bool lineEmpty = true;
    while (words >> word) {
        if (!lineEmpty && column + 1 + word.size() > width) {
            out += "\n" + std::string(indent, ' ');
            column = indent;
            lineEmpty = true;
        }
        if (!lineEmpty) {
            out += ' ';
            ++column;
        }
        out += word;
        column += word.size();
        lineEmpty = false;
    }
    return out;
}

} // namespace

const std::vector<MethodOption>& methodOptions() {
    static const std::vector<MethodOption> options = declareOptions();
    return options;
}

const MethodOption* findMethodOption(std::string_view name) {
    for (const MethodOption& o : methodOptions())
        if (o.name == name) return &o;
    return nullptr;
}

void setMethodOption(MethodSettings& settings, const MethodOption& option, const std::string& value) {
    const std::string flag = "--" + option.name;
    if (value == kDefault && option.get(MethodSettings{}) == kDefault) return option.set(settings, value);
    switch (option.kind) {
    case Kind::Choice:
        for (const std::string& c : option.choices)
            if (value == c) return option.set(settings, value);
        throw std::invalid_argument(flag + " '" + value + "' is not one of: " + joined(option.choices, ", "));
    case Kind::Count: {
        unsigned long v = 0;
        const auto [end, error] = std::from_chars(value.data(), value.data() + value.size(), v);
        if (error != std::errc() || end != value.data() + value.size() || double(v) < option.lo ||
            double(v) > option.hi)
            throw std::invalid_argument(flag + " '" + value + "' is not an integer in " +
                                        numberText(option.lo) + ".." + numberText(option.hi));
        return option.set(settings, value);
    }
    case Kind::Number: {
        if (std::find(option.words.begin(), option.words.end(), value) != option.words.end())
            return option.set(settings, value);
        double v = 0.0;
        const auto [end, error] = std::from_chars(value.data(), value.data() + value.size(), v);
        if (error != std::errc() || end != value.data() + value.size() || !(v >= option.lo && v <= option.hi))
            throw std::invalid_argument(flag + " '" + value + "' is not a number in [" +
                                        numberText(option.lo) + ", " + numberText(option.hi) + "]" +
                                        (option.words.empty() ? "" : " or " + joined(option.words, ", ")));
        return option.set(settings, value);
    }
    case Kind::Text:
        return option.set(settings, value);
    }
}

bool methodReadsOption(const MethodOption& option, const std::string& method) {
    if (option.methods == "all") return true;
    std::istringstream methods(option.methods);
    for (std::string m; std::getline(methods >> std::ws, m, ',');) {
        const bool family = !m.empty() && m.back() == '*';
        if (family ? method.rfind(m.substr(0, m.size() - 1), 0) == 0 : method == m) return true;
    }
    return false;
}

std::string methodSettingsKey(const MethodSettings& settings) {
    std::string key;
    for (const MethodOption& o : methodOptions())
        key += o.name + "=" + o.get(settings) + ";";
    // A replaced program by its name and its code's address: two builds are two renders.
    for (const auto& [name, code] : settings.agaa.programs) {
        char address[32];
        std::snprintf(address, sizeof address, "%p", static_cast<const void*>(code.data()));
        key += "program:" + name + "@" + address + ";";
    }
    return key;
}

// Joins a flag and its value in the synopsis so that lines wrap between flags only.
constexpr char kGlue = '\x1f';

std::string methodOptionsSynopsis(size_t indent, size_t width) {
    std::string flags;
    for (const MethodOption& o : methodOptions())
        flags += (flags.empty() ? "" : " ") + ("[--" + o.name + kGlue + o.syntax + "]");
    std::string out = wrapped(flags, indent, width, indent);
    std::replace(out.begin(), out.end(), kGlue, ' ');
    return std::string(indent, ' ') + out;
}

std::string methodOptionsHelp(size_t width) {
    std::string out;
    for (const MethodOption& o : methodOptions()) {
        const std::string head = "  --" + o.name + " " + o.syntax;
        const std::string body = o.doc + " (" + o.methods + "; default " + o.defaultText + ")";
        out += head + "\n" + std::string(20, ' ') + wrapped(body, 20, width, 20) + "\n";
    }
    return out;
}

} // namespace agaa
