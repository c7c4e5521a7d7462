#ifndef AGAA_REFERENCE_GBUFFER_INPUTS_GLSL
#define AGAA_REFERENCE_GBUFFER_INPUTS_GLSL
// reference/gbuffer.vert's outputs, as the fragment shaders it feeds read them (the per-sample
// G-buffer, SBAA's prepass and fill). GBUFFER_SAMPLE_RATE 1: interpolated at each sample's own
// position, so what runs per sample sees that sample's values. Sample shading alone would only
// run more invocations: without the `sample` qualifier each may still read the pixel-centre values.
// At pixel rate: at the centroid, inside the triangle and the covered samples. At the pixel centre
// a thin triangle's normal was extrapolated far outside it: the reference's metal lattice lost
// 18 % of its mean radiance at 64x64 that way (0.370 against 0.454 at sample rate, issue 14).
#ifndef GBUFFER_SAMPLE_RATE
#define GBUFFER_SAMPLE_RATE 0
#endif
#if GBUFFER_SAMPLE_RATE
#define INTERPOLATION sample
#else
#define INTERPOLATION centroid
#endif
layout(location = 0) INTERPOLATION in vec3 inNormal; // view space
layout(location = 1) INTERPOLATION in vec4 inTangent;
layout(location = 2) INTERPOLATION in vec4 inUvs; // xy TEXCOORD_0, zw TEXCOORD_1
layout(location = 3) INTERPOLATION in vec4 inColor;
#endif
