#pragma once
// The method settings (MethodSettings, agaa/common/technique.h) declared once: each option's
// name, the values it takes, its default, what it does and which methods read it. agaa-render's
// flags and --help, the README's synopsis (checked by the test cli.readme_synopsis) and the render
// cache's key (tools/harness/frame_renderer.cpp) all come from this table.

#include "agaa/common/technique.h"

#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace agaa {

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
