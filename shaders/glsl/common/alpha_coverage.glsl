#ifndef AGAA_ALPHA_COVERAGE_GLSL
#define AGAA_ALPHA_COVERAGE_GLSL
// Masked (glTF alphaMode MASK) materials in the visibility / G-buffer passes (paper section 3.6).
// Path 1 (one sample per pixel): discard below the cutoff. Path 2 (MSAA): alpha-to-coverage
// (the pipeline's alphaToCoverageEnable reads the alpha of colour output 0) with the alpha
// sharpened around the cutoff, (alpha - cutoff) / fwidth(alpha) + 1/2: the edge keeps the glTF
// cutoff's position and is anti-aliased over about one pixel instead of dithering the whole
// translucent ramp. Later passes (AGAA generation, depth EQUAL) inherit the coverage from the
// depth buffer and sample no alpha.
// Call in uniform control flow (fwidth); the path is a specialisation constant.
const float kMinAlphaWidth = 1.0e-4; // flat alpha: a step at the cutoff

float maskedCoverage(uint path, float alpha, float cutoff) {
    if (path == 1u) {
        if (alpha < cutoff) discard;
        return 1.0;
    }
    return clamp((alpha - cutoff) / max(fwidth(alpha), kMinAlphaWidth) + 0.5, 0.0, 1.0);
}
#endif
