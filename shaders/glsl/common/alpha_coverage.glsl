#ifndef AGAA_ALPHA_COVERAGE_GLSL
#define AGAA_ALPHA_COVERAGE_GLSL
// Masked (glTF alphaMode MASK) and blended (BLEND) materials in the visibility / G-buffer passes
// (paper section 3.6).
// Path 1 (one sample per pixel): discard below the cutoff. Path 2 (MSAA): alpha-to-coverage
// (the pipeline's alphaToCoverageEnable reads the alpha of colour output 0) with the alpha
// sharpened around the cutoff, (alpha - cutoff) / fwidth(alpha) + 1/2: the edge keeps the glTF
// cutoff's position and is anti-aliased over about one pixel instead of dithering the whole
// translucent ramp. Later passes (AGAA generation, depth EQUAL) inherit the coverage from the
// depth buffer and sample no alpha.
// Call in uniform control flow (fwidth); the path is a specialisation constant.
const float kMinAlphaWidth = 1.0e-4; // flat alpha: a step at the cutoff

// BLEND materials (issue 16, agaa/common/effects.h AlphaPath): path 3 (MSAA) hands the alpha
// itself to alpha-to-coverage, translucency as the fraction of samples covered; path 4 (one
// sample per pixel) keeps the fragment where the alpha exceeds an ordered 4x4 (Bayer) threshold,
// so a region of alpha a keeps about a of its pixels.
float maskedCoverage(uint path, float alpha, float cutoff) {
    if (path == 1u) {
        if (alpha < cutoff) discard;
        return 1.0;
    }
    if (path == 3u) return clamp(alpha, 0.0, 1.0);
    if (path == 4u) {
        const float bayer[16] = float[](0.0, 8.0, 2.0, 10.0, 12.0, 4.0, 14.0, 6.0, 3.0, 11.0, 1.0, 9.0, 15.0, 7.0,
                                        13.0, 5.0);
        ivec2 p = ivec2(gl_FragCoord.xy) & 3;
        if (alpha <= (bayer[p.y * 4 + p.x] + 0.5) / 16.0) discard;
        return 1.0;
    }
    return clamp((alpha - cutoff) / max(fwidth(alpha), kMinAlphaWidth) + 0.5, 0.0, 1.0);
}
#endif
