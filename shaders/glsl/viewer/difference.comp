#version 460
// agaa-viewer's difference view: |method - reference| of the tone-mapped display images (linear
// [0,1]), per channel, scaled by the gain so that small anti-aliasing errors are visible; the
// display blit then sRGB-encodes it like any frame.
layout(local_size_x = 16, local_size_y = 16) in;

layout(set = 0, binding = 0) uniform sampler2D methodDisplay;
layout(set = 0, binding = 1) uniform sampler2D referenceDisplay;
layout(set = 0, binding = 2, rgba32f) uniform writeonly image2D outDifference;
layout(push_constant) uniform Push { float gain; };

void main() {
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(pixel, imageSize(outDifference)))) return;
    vec3 a = texelFetch(methodDisplay, pixel, 0).rgb;
    vec3 b = texelFetch(referenceDisplay, pixel, 0).rgb;
    imageStore(outDifference, pixel, vec4(min(abs(a - b) * gain, vec3(1.0)), 1.0));
}
