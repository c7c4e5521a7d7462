// Step 3 of AGAA's lighting pass (agaa/lighting/lighting_pass.glsl), defined after it by the builds
// that light: every present aggregate of the pixel shaded once, on the schedule
// agaa/lighting/schedule.glsl chose; c = 1's off-layer samples with aggregate 0. A pixel the shading rate flags has no aggregate present: its samples are shaded
// by the pass after this one (agaa/lighting_per_sample.comp).
void shadeAggregates(OffLayer off, bool inside, uint firstEntry, out OffLayerShading offShaded) {
    shaded = Shading[](noShading(), noShading(), noShading(), noShading());
    offShaded = noOffLayerShading();
    if (kCompactShading != 0u) {
        shadeTileList(firstEntry);
        // Aggregate 0 of every covered pixel: every lane of a SIMD group busy but for sky pixels.
        // After the list's rounds: no barrier follows it, so lavapipe (whose compute barriers
        // split the shader into coroutine segments) keeps its loop free of frame spills.
        if (inside && aggregates[0].present) shadeAggregate(aggregates[0], off, shaded[0], offShaded);
    } else if (inside) {
        if (aggregates[0].present) shadeAggregate(aggregates[0], off, shaded[0], offShaded);
        for (uint a = 1u; a < kAggregates; ++a) {
            if (!aggregates[a].present) continue;
            OffLayerShading unused; // no off-layer samples beyond aggregate 0
            shadeAggregate(aggregates[a], noOffLayer(aggregates[a]), shaded[a], unused);
        }
    }
}
