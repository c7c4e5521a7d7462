#ifndef AGAA_HALF_GLSL
#define AGAA_HALF_GLSL
// Half-float unpacking in integer arithmetic, exact for every half (subnormals, infinities and
// NaN included), as unpackHalf2x16 is. Not unpackHalf2x16 itself: on a CPU without F16C (Intel
// before Ivy Bridge, and VM CPU models that hide it) Mesa 22.3's llvmpipe builds an fpext of an
// integer vector for it, and the release LLVM then jumps into the middle of an instruction
// (SIGILL; docs/cross-cpu.md).

float halfBitsToFloat(uint h) {
    uint e = (h >> 10u) & 0x1Fu, m = h & 0x3FFu;
    float magnitude = e == 0u    ? float(m) * uintBitsToFloat(0x33800000u) // m 2^-24: zero and subnormals
                      : e == 31u ? uintBitsToFloat(0x7F800000u | (m << 13u)) // infinity, NaN
                                 : uintBitsToFloat(((e + 112u) << 23u) | (m << 13u));
    return uintBitsToFloat(floatBitsToUint(magnitude) | ((h & 0x8000u) << 16u));
}

vec2 unpackHalf2x16Exact(uint w) { return vec2(halfBitsToFloat(w & 0xFFFFu), halfBitsToFloat(w >> 16u)); }
#endif
