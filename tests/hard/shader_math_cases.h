#pragma once
// The edge cases of the shared shader math (shaders/glsl/tests/shader_math.comp runs them on the
// GPU), each with the epsilon guards of shaders/glsl/common/epsilon.glsl it drives to their edge
// and a check against a double-precision CPU twin. The same list feeds the GPU test and the
// epsilon-coverage test, so a guard counts as covered only if a case that runs names it.

#include <glm/glm.hpp>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace agaa::hard {

// std430 mirrors of the kernel's structs (vec4/uvec4 members only: no padding questions).
struct MathCase {
    glm::uvec4 op{0u};
    glm::vec4 a{0.0f}, b{0.0f}, c{0.0f}, d{0.0f}, e{0.0f};
};
struct MathResult {
    glm::vec4 r0{0.0f}, r1{0.0f};
};
static_assert(sizeof(MathCase) == 96 && sizeof(MathResult) == 32);

enum MathOp : uint32_t {
    kOpOctahedral = 0,
    kOpOctDecode = 1,
    kOpHemisphere = 2,
    kOpGgxD = 3,
    kOpSmith = 4,
    kOpFresnel = 5,
    kOpBrdf = 6,
    kOpLight = 7,
    kOpRangeWindow = 8,
    kOpToneMap = 9,
    kOpToksvig = 10,
    kOpFiltered = 11,
    kOpQuantize = 12,
    kOpMean = 13,
    kOpMaterial = 14,
    kOpDepth = 15,
    kOpPlaneTolerance = 16,
    kOpShadeEvent = 17,
    kOpBrdfAniso = 18,
    kOpSggxLobe = 19,
    kOpToneMapAggregate = 20,
    kOpCurvature = 21,
    kOpPixelFootprint = 22,
    kOpFaceNormal = 23,
    kOpFilteredCosine = 24,
    kOpAggregateWidth = 25,
    kOpEnvironmentRoughness = 26,
    kOpMeanNormalLobe = 27,
    kOpViewFootprint = 28,
    kOpBrdfFiltered = 29,
    kOpSrgbEncode = 30,
    kOpSrgbDecode = 31,
};

struct EdgeCase {
    std::string name;
    std::vector<std::string> guards; // epsilon.glsl constants this case drives to their edge
    MathCase input;
    // Empty when the GPU result passes; otherwise what is wrong (value, expected, tolerance).
    std::function<std::string(const MathResult&)> check;
};

std::vector<EdgeCase> shaderMathCases();
// The footprint cases (shader_math_footprint_cases.cpp), appended to `cases`.
void addFootprintCases(std::vector<EdgeCase>& cases);
// The curvature roughness's cases (shader_math_roughness_cases.cpp), appended to `cases`.
void addCurvatureRoughnessCases(std::vector<EdgeCase>& cases);
// The sRGB encode and decode cases (shader_math_srgb_cases.cpp), appended to `cases`.
void addSrgbCases(std::vector<EdgeCase>& cases);

// The `const float kName` constants declared in epsilon.glsl, in file order.
std::vector<std::string> epsilonConstants(const std::string& epsilonGlslPath);

} // namespace agaa::hard
