#pragma once
// The method settings (MethodSettings) declared once: each option's
// name, the values it takes, its default, what it does and which methods read it. agaa-render's
// flags and --help, the README's synopsis (checked by the test cli.readme_synopsis) and the render
// cache's key (tools/harness/frame_renderer.cpp) all come from this table.

#include "agaa/aggregate/agaa_constants.h"
#include "agaa/common/technique.h"

#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace agaa {

// Settings every method understands; a method ignores the ones it has no use for.
struct MethodSettings {
    uint32_t samples = 8;    // n: visibility samples per pixel
    uint32_t aggregates = 2; // c: AGAA aggregates per pixel
    // S: surfaces per pixel; 0 = the method's default (SBAA: 4 of 1..6; streaming: 3 of 1..3).
    uint32_t surfaces = 0;
    // Streaming compression's normal threshold alpha in degrees; negative = the paper's pi/4.
    float streamingNormalAngle = -1.0f;
    std::string debug; // a method's debug view ("" = none), e.g. "aggregates" for agaa
    // AGAA clustering (Equation 1): characteristic length k in metres and the seed threshold t;
    // negative = the method's documented default.
    float characteristicLength = -1.0f;
    float seedThreshold = -1.0f;
    // AGAA shading position: false = mean of the aggregate's sample positions, true = the UE4
    // shortcut (seed 004): the mean depth on the pixel centre's ray.
    bool pixelCentrePosition = false;
    // AGAA's choices (agaa/aggregate/agaa_constants.h, where each says what it does and what Auto
    // resolves to): what AggregateSettings takes of them, as they are.
    AggregateChoices agaa;
    // The fill pass of the per-sample G-buffer (reference, Simple/Complex, AGAA's samples path):
    // sample-rate shading (supersampled materials) instead of pixel rate with per-sample coverage.
    bool sampleRateShading = false;
    // AGAA samples path: Kaplanyan curvature roughness in the fill pass (seed 004).
    EffectSettings effects; // scene-driven shadows, alpha-to-coverage, emissive, normal maps
};

struct MethodOption {
    enum class Kind {
        Choice, // one of `choices`
        Count,  // a whole number in [lo, hi]
        Number, // a number in [lo, hi]
        Text,   // any text; the method checks it (a debug view)
    };
    std::string name;   // the flag without "--": "agaa-ndf"
    std::string syntax; // its value in the synopsis: "K", or the choices joined by '|'
    Kind kind = Kind::Choice;
    std::vector<std::string> choices;
    double lo = 0.0, hi = 0.0;
    std::vector<std::string> words; // Number: the words it also takes instead of a number ("never")
    std::string defaultText;        // what the default does, in the value's own words
    std::string doc;                // one paragraph for --help
    // The methods that read it: "all", or names, "family*" for every method whose name starts with
    // it: "agaa*" is agaa, agaa-accumulate and agaa-samples.
    std::string methods;
    // The setting in MethodSettings: `set` takes a value already checked against kind, choices
    // and range; `get` gives the text `set` would take for the same behaviour.
    std::function<void(MethodSettings&, const std::string&)> set;
    std::function<std::string(const MethodSettings&)> get;
};

const std::vector<MethodOption>& methodOptions();

// The option called `name` (without "--"), or nullptr.
const MethodOption* findMethodOption(std::string_view name);

// Checks `value` against the option and sets it; "default" restores the method's own default of
// the options whose default depends on the method (surfaces) or is the paper's (the clustering
// constants, streaming's angle). Throws std::invalid_argument naming the flag,
// the value and the allowed values: "--agaa-ndf 'lean' is not one of: auto, sggx, toksvig".
void setMethodOption(MethodSettings& settings, const MethodOption& option, const std::string& value);

// Whether `method` (agaa-render's name, e.g. "agaa-samples") reads the option (its `methods`).
bool methodReadsOption(const MethodOption& option, const std::string& method);

// Every setting as "name=value" (and each replaced AGAA program), ';'-separated: two settings with
// the same key render the same technique.
std::string methodSettingsKey(const MethodSettings& settings);

// "[--name SYNTAX]" for every option, wrapped at `width` columns, lines after the first indented
// by `indent` spaces.
std::string methodOptionsSynopsis(size_t indent, size_t width);

// Each option's --help paragraph: "  --name SYNTAX  doc (methods; default ...)", wrapped.
std::string methodOptionsHelp(size_t width);

} // namespace agaa
