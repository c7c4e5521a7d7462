#ifndef AGAA_SHARED_GLSL_CPP_H
#define AGAA_SHARED_GLSL_CPP_H
// Lets one struct definition compile as GLSL and as C++ (niagara-style), so the
// layouts of uniform and storage buffers cannot drift. Members are vec4/mat4/
// uvec4/ivec4 only: identical under std140, std430 and C++ alignment.
#ifdef __cplusplus
#include <cmath>
#include <cstdint>
#include <glm/glm.hpp>
namespace shared {
using vec3 = glm::vec3; // shader math only (shared/sggx.h), never in buffer structs
using mat3 = glm::mat3;
using glm::cross;
using glm::dot;
using std::abs;
using vec4 = glm::vec4;
using uvec4 = glm::uvec4;
using ivec4 = glm::ivec4;
using mat4 = glm::mat4;
using uint = uint32_t;
using std::floor;
using std::sqrt;
} // namespace shared
#define SHARED_BEGIN namespace shared {
#define SHARED_END }
#define SHARED_CONST inline constexpr uint32_t
#define SHARED_CONST_FLOAT inline constexpr float
#define inline_fn inline
#define inout_param(T) T& // a GLSL inout parameter
#else
#define inline_fn
#define inout_param(T) inout T
#define SHARED_BEGIN
#define SHARED_END
#define SHARED_CONST const uint
#define SHARED_CONST_FLOAT const float
#endif
#endif
