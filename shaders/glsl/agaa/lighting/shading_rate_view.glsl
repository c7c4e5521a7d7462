// --debug shading-rate (AggregateDebugView::ShadingRate): the lit image's luminance, in red where
// the pixel was shaded per sample (agaa/lighting_per_sample.comp) and in grey elsewhere
// (agaa/lighting.comp).
vec3 shadingRateView(vec3 display, bool perSample) {
    float luminance = dot(display, vec3(0.2126, 0.7152, 0.0722));
    float shade = 0.25 + 0.75 * luminance; // flagged dark pixels stay visible
    return perSample ? shade * vec3(1.0, 0.15, 0.1) : vec3(0.6 * luminance);
}
