// The method settings' one declaration (agaa/method_settings.h): every option round-trips, every
// option moves the render cache's key, and bad values are refused with the flag and the allowed
// values. No device.

#include "agaa/aggregate/agaa_constants.h"
#include "agaa/common/named_value.h"
#include "agaa/method_settings.h"
#include "agaa/methods.h"

#include <gtest/gtest.h>

#include <set>
#include <stdexcept>
#include <type_traits>

namespace {

using agaa::MethodOption;
using agaa::MethodSettings;

// A valid value of `o` other than the one `settings` holds.
std::string otherValue(const MethodOption& o, const MethodSettings& settings) {
    const std::string current = o.get(settings);
    switch (o.kind) {
    case MethodOption::Kind::Choice:
        for (const std::string& c : o.choices)
            if (c != current) return c;
        break;
    case MethodOption::Kind::Count:
        return std::to_string(uint64_t(o.lo) == std::stoull(current == "default" ? "0" : current)
                                  ? uint64_t(o.hi)
                                  : uint64_t(o.lo));
    case MethodOption::Kind::Number:
        return current == "1" ? "2" : "1";
    case MethodOption::Kind::Text:
        return current + "x";
    }
    ADD_FAILURE() << o.name << " has a single value";
    return current;
}

TEST(MethodSettings, EveryOptionIsDeclaredOnceWithItsDocAndMethods) {
    std::set<std::string> names;
    for (const MethodOption& o : agaa::methodOptions()) {
        EXPECT_TRUE(names.insert(o.name).second) << o.name << " is declared twice";
        EXPECT_FALSE(o.doc.empty()) << o.name;
        EXPECT_FALSE(o.methods.empty()) << o.name;
        EXPECT_FALSE(o.defaultText.empty()) << o.name;
        // --help and the README's synopsis print defaultText; a default changed in MethodSettings
        // alone would make them lie. "default" and "" defer to the technique's own settings struct
        // (the test below).
        const std::string held = o.get(MethodSettings{});
        if (held != "default" && !held.empty()) {
            EXPECT_EQ(o.defaultText, held) << o.name << ": the documented default is the default";
        }
        EXPECT_EQ(agaa::findMethodOption(o.name), &o);
    }
    EXPECT_EQ(agaa::findMethodOption("no-such-option"), nullptr);
    EXPECT_EQ(agaa::findMethodOption("--samples"), nullptr) << "names are given without the dashes";
}

// A host that fills AggregateSettings itself gets what agaa-render's defaults give.
TEST(MethodSettings, AgaaDefaultsAreTheHostApisDefaults) {
    const MethodSettings m;
    const agaa::AggregateSettings a;
    // AGAA's own choices are one struct on both sides (AggregateChoices): the same defaults by
    // construction. What the method table shares with every method is copied.
    static_assert(std::is_base_of_v<agaa::AggregateChoices, agaa::AggregateSettings>);
    static_assert(std::is_same_v<decltype(MethodSettings::agaa), agaa::AggregateChoices>);
    EXPECT_EQ(m.samples, a.samples);
    EXPECT_EQ(m.aggregates, a.aggregates);
    EXPECT_EQ(a.tolerance, agaa::kToleranceAuto);
    EXPECT_EQ(a.aliasLimit, agaa::kDefaultAliasLimit);
    EXPECT_EQ(agaa::findMethodOption("agaa-tolerance")->defaultText, "auto");
    EXPECT_EQ(agaa::findMethodOption("agaa-alias-limit")->defaultText, "5000");
    EXPECT_EQ(agaa::findMethodOption("characteristic-length")->defaultText, "0.1");
    EXPECT_FLOAT_EQ(a.characteristicLength, 0.1f) << "--help's characteristic-length default";
    EXPECT_EQ(agaa::findMethodOption("seed-threshold")->defaultText, "0.05");
    EXPECT_FLOAT_EQ(a.seedThreshold, 0.05f) << "--help's seed-threshold default";
}

TEST(MethodSettings, EveryOptionRoundTripsAndMovesTheCacheKey) {
    const MethodSettings defaults;
    const std::string defaultKey = agaa::methodSettingsKey(defaults);
    for (const MethodOption& o : agaa::methodOptions()) {
        MethodSettings s;
        const std::string value = otherValue(o, s);
        agaa::setMethodOption(s, o, value);
        EXPECT_EQ(o.get(s), value) << o.name << ": get gives what set took";
        MethodSettings back = s;
        agaa::setMethodOption(back, o, o.get(defaults));
        EXPECT_EQ(agaa::methodSettingsKey(back), defaultKey)
            << o.name << ": the default's text sets the default";
        // The key sees every option: before this table it was a hand-written concatenation that
        // could miss one, and two techniques would then share a cache entry.
        EXPECT_NE(agaa::methodSettingsKey(s), defaultKey) << o.name << " does not reach the key";
        for (const MethodOption& other : agaa::methodOptions()) {
            if (&other == &o) continue;
            EXPECT_EQ(other.get(s), other.get(defaults)) << o.name << " moved " << other.name;
        }
    }
    // A replaced program is part of the key, by name and by build: agaa-timings' breakdown renders
    // the same settings with three sets of builds.
    static const uint32_t buildA[] = {0x07230203u}, buildB[] = {0x07230203u, 0u};
    MethodSettings replaced, replacedOther, replacedElsewhere;
    replaced.agaa.programs["agaa/lighting.comp"] = buildA;
    replacedOther.agaa.programs["agaa/lighting.comp"] = buildB;
    replacedElsewhere.agaa.programs["agaa/visibility.frag"] = buildA;
    const std::string keys[] = {defaultKey, agaa::methodSettingsKey(replaced),
                                agaa::methodSettingsKey(replacedOther),
                                agaa::methodSettingsKey(replacedElsewhere)};
    for (size_t i = 0; i < std::size(keys); ++i)
        for (size_t j = i + 1; j < std::size(keys); ++j)
            EXPECT_NE(keys[i], keys[j]) << "keys " << i << " and " << j;
}

TEST(MethodSettings, BadValuesNameTheFlagAndTheAllowedValues) {
    MethodSettings s;
    auto message = [&](const char* name, const std::string& value) -> std::string {
        try {
            agaa::setMethodOption(s, *agaa::findMethodOption(name), value);
        } catch (const std::invalid_argument& e) {
            return e.what();
        }
        return "accepted";
    };
    EXPECT_EQ(message("samples", "3"), "--samples '3' is not one of: 1, 4, 8, 16, 32");
    EXPECT_EQ(message("agaa-ndf", "lean"), "--agaa-ndf 'lean' is not one of: auto, sggx, toksvig");
    EXPECT_EQ(message("aggregates", "5"), "--aggregates '5' is not an integer in 1..4");
    EXPECT_EQ(message("aggregates", "0"), "--aggregates '0' is not an integer in 1..4");
    EXPECT_EQ(message("aggregates", "2x"), "--aggregates '2x' is not an integer in 1..4");
    EXPECT_EQ(message("aggregates", "-1"), "--aggregates '-1' is not an integer in 1..4");
    EXPECT_EQ(message("shadow-map-size", ""), "--shadow-map-size '' is not an integer in 64..4096");
    EXPECT_EQ(message("streaming-normal-angle", "91"),
              "--streaming-normal-angle '91' is not a number in [0.001, 90]");
    EXPECT_EQ(message("streaming-normal-angle", "nan"),
              "--streaming-normal-angle 'nan' is not a number in [0.001, 90]");
    EXPECT_EQ(message("seed-threshold", "0.1.2"), "--seed-threshold '0.1.2' is not a number in [0, 1000000]");
    EXPECT_EQ(message("agaa-tolerance", "always"),
              "--agaa-tolerance 'always' is not a number in [0, 10000000] or auto, never");
    EXPECT_EQ(message("agaa-alias-limit", "0"),
              "--agaa-alias-limit '0' is not a number in [1, 10000000] or none");
    EXPECT_EQ(message("agaa-generation", "coverage"), "accepted") << "refused later, by the device (exit 3)";
    EXPECT_EQ(message("surfaces", "default"), "accepted");
    EXPECT_EQ(message("aggregates", "default"), "--aggregates 'default' is not an integer in 1..4")
        << "c's default does not depend on the method: it is 2";
    EXPECT_EQ(s.agaa.generation, agaa::AggregateGeneration::Coverage);
    EXPECT_EQ(s.aggregates, 2u) << "a refused value leaves the setting alone";
}

TEST(MethodSettings, EachOptionNamesTheMethodsThatReadIt) {
    const auto reads = [](const char* option, const char* method) {
        return agaa::methodReadsOption(*agaa::findMethodOption(option), method);
    };
    EXPECT_TRUE(reads("samples", "noaa")) << "all";
    EXPECT_TRUE(reads("agaa-ndf", "agaa-samples")) << "the agaa family";
    EXPECT_FALSE(reads("agaa-ndf", "reference"));
    EXPECT_TRUE(reads("surfaces", "streaming"));
    EXPECT_FALSE(reads("surfaces", "agaa"));
    EXPECT_TRUE(reads("sample-rate-shading", "simple-complex-naive")) << "the simple-complex family";
    EXPECT_FALSE(reads("sample-rate-shading", "fxaa"));
    EXPECT_TRUE(reads("agaa-generation", "agaa"));
    EXPECT_FALSE(reads("agaa-generation", "agaa-samples")) << "the path methods pin their own";
    for (const MethodOption& o : agaa::methodOptions()) {
        bool someone = false;
        for (const agaa::MethodInfo& m : agaa::knownMethods())
            someone = someone || agaa::methodReadsOption(o, m.name);
        EXPECT_TRUE(someone) << o.name << " names no known method: '" << o.methods << "'";
    }
}

TEST(MethodSettings, SynopsisAndHelpHoldEveryOption) {
    const std::string synopsis = agaa::methodOptionsSynopsis(4, 60);
    const std::string help = agaa::methodOptionsHelp(80);
    size_t lineStart = 0;
    for (size_t end = synopsis.find('\n'); lineStart < synopsis.size();
         lineStart = end + 1, end = synopsis.find('\n', lineStart)) {
        const std::string line = synopsis.substr(lineStart, end == std::string::npos ? end : end - lineStart);
        EXPECT_EQ(line.rfind("    [--", 0), 0u) << "indented, whole flags only: '" << line << "'";
        EXPECT_TRUE(line.size() <= 60 || line.find("] [") == std::string::npos) << "wrapped at 60: " << line;
        if (end == std::string::npos) break;
    }
    for (const MethodOption& o : agaa::methodOptions()) {
        EXPECT_NE(synopsis.find("[--" + o.name + " " + o.syntax + "]"), std::string::npos) << o.name;
        EXPECT_NE(help.find("  --" + o.name + " " + o.syntax + "\n"), std::string::npos) << o.name;
    }
}

} // namespace
