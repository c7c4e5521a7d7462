// Every named guard constant of shaders/glsl/common/epsilon.glsl is driven to its edge by at
// least one shader-math case (by name), and every name a case claims exists in the header.

#include "shader_math_cases.h"

#include <gtest/gtest.h>

#include <map>
#include <set>

TEST(HardEpsilonCoverage, EveryEpsilonConstantHasAnEdgeCase) {
    const std::vector<std::string> constants = agaa::hard::epsilonConstants(AGAA_EPSILON_GLSL);
    ASSERT_GE(constants.size(), 8u) << AGAA_EPSILON_GLSL
                                    << ": expected the named guard constants (parse failed?)";
    std::map<std::string, std::vector<std::string>> table; // constant -> the cases that exercise it
    for (const auto& c : agaa::hard::shaderMathCases())
        for (const std::string& g : c.guards)
            table[g].push_back(c.name);
    const std::set<std::string> declared(constants.begin(), constants.end());
    for (const std::string& name : constants) {
        EXPECT_FALSE(table[name].empty())
            << name << " (epsilon.glsl) has no shader-math edge case: add one to "
            << "tests/hard/shader_math_cases.cpp that drives it to its boundary";
        std::printf("[ measured ] %-22s %zu case(s), e.g. \"%s\"\n", name.c_str(), table[name].size(),
                    table[name].empty() ? "-" : table[name].front().c_str());
    }
    for (const auto& [name, cases] : table)
        EXPECT_TRUE(declared.count(name)) << "case \"" << cases.front() << "\" names guard " << name
                                          << ", which epsilon.glsl does not declare";
}
