// AGAA's program selection (agaa/aggregate/passes/aggregate_programs.h) against the shader table's
// generated index: every variant a pass can ask for is a program of the table, distinct variants
// are distinct programs, and the override check knows exactly the table's AGAA programs.

#include "agaa/aggregate/passes/aggregate_programs.h"

#include <gtest/gtest.h>

#include <set>
#include <stdexcept>
#include <string>

namespace {

TEST(AggregatePrograms, EveryVariantIsAProgramOfTheTableAndDistinctVariantsAreDistinct) {
    std::set<std::string> generation, lighting, perSample;
    for (int i = 0; i < 8; ++i) {
        const bool a = i & 4, b = i & 2, c = i & 1;
        const agaa::NamedProgram g = agaa::generationProgram(a, b, c);
        EXPECT_FALSE(g.code.empty()) << g.name;
        generation.insert(std::string(g.name));
        lighting.insert(std::string(agaa::lightingProgram(a, b, c).name));
        perSample.insert(std::string(agaa::perSampleProgram(a, b, c).name));
    }
    EXPECT_EQ(generation.size(), 8u);
    EXPECT_EQ(lighting.size(), 8u);
    // The samples path's G-buffer holds its emissive: 2 programs there, 4 on the accumulate path.
    EXPECT_EQ(perSample.size(), 6u);
    EXPECT_EQ(agaa::perSampleProgram(false, true, true).name,
              agaa::perSampleProgram(false, false, true).name);
    EXPECT_EQ(agaa::lightingProgram(true, false, true).name, "agaa/lighting_gbuffer_shadow.comp");
    EXPECT_EQ(agaa::generationProgram(true, true, false).name, "agaa/generation_emissive_int64.frag");
    EXPECT_NE(agaa::clusterProgram(false).name, agaa::clusterProgram(true).name);
    EXPECT_FALSE(agaa::visibilityProgram().code.empty());
    EXPECT_FALSE(agaa::aggregatesViewProgram().code.empty());
}

TEST(AggregatePrograms, TheOverrideCheckKnowsTheTablesAgaaProgramsOnly) {
    agaa::ProgramOverrides every;
    for (const agaa::NamedProgram& p : agaa::aggregatePrograms()) {
        EXPECT_EQ(p.name.substr(0, 5), "agaa/");
        every[std::string(p.name)] = p.code;
    }
    EXPECT_NO_THROW(agaa::checkProgramOverrides(every));
    agaa::ProgramOverrides misspelt{
        {"agaa/lighting_gbufer.comp", agaa::lightingProgram(true, false, false).code}};
    try {
        agaa::checkProgramOverrides(misspelt);
        ADD_FAILURE() << "a misspelt program name was accepted";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("'agaa/lighting_gbufer.comp'"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("agaa/lighting_gbuffer.comp"), std::string::npos) << e.what();
    }
}

} // namespace
