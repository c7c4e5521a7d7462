#pragma once
// What the shader-math case lists share (shader_math_cases.cpp, shader_math_footprint_cases.cpp):
// building one case and comparing a GPU result with its double twin, with a message that says
// what is wrong.

#include "shader_math_cases.h"

#include <glm/glm.hpp>

#include <cmath>
#include <sstream>
#include <string>

namespace agaa::hard::checks {

using D3 = glm::dvec3;

// Default tolerance of one fp32 expression chain against double.
inline constexpr double kRel = 2.0e-5, kAbs = 1.0e-6;

inline std::string fmt(double v) {
    std::ostringstream s;
    s.precision(9);
    s << v;
    return s.str();
}

inline std::string near(const std::string& what, double got, double want, double rel = kRel,
                        double abs = kAbs) {
    if (!std::isfinite(got)) return what + " = " + fmt(got) + " is not finite (expected " + fmt(want) + ")";
    if (std::abs(got - want) > abs + rel * std::abs(want))
        return what + " = " + fmt(got) + ", expected " + fmt(want) + " (tolerance " + fmt(abs) + " + " +
               fmt(rel) + " relative)";
    return {};
}

inline std::string near3(const std::string& what, glm::vec3 got, D3 want, double rel = kRel,
                         double abs = kAbs) {
    for (int i = 0; i < 3; ++i)
        if (std::string e = near(what + "[" + std::to_string(i) + "]", got[i], want[i], rel, abs); !e.empty())
            return e;
    return {};
}

inline std::string finite3(const std::string& what, glm::vec3 v) {
    for (int i = 0; i < 3; ++i)
        if (!std::isfinite(v[i]))
            return what + "[" + std::to_string(i) + "] = " + fmt(v[i]) + " is not finite";
    return {};
}

inline std::string unitLength(const std::string& what, glm::vec3 v) {
    if (std::string e = finite3(what, v); !e.empty()) return e;
    return near("|" + what + "|", glm::length(glm::dvec3(v)), 1.0, 1e-5, 0.0);
}

inline MathCase op(uint32_t o, glm::vec4 a = {}, glm::vec4 b = {}, glm::vec4 c = {}, glm::vec4 d = {},
                   glm::vec4 e = {}) {
    MathCase m;
    m.op = {o, 0u, 0u, 0u};
    m.a = a;
    m.b = b;
    m.c = c;
    m.d = d;
    m.e = e;
    return m;
}

} // namespace agaa::hard::checks
