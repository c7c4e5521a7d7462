// Binding 7 of the accumulation kernel's builds that keep each covered sample's material for the
// shading rate (kSampleMaterial; shared/sample_material.h): the shipping pass and the breakdown's
// material-only build. After agaa/generation/fragment.glsl.
layout(set = 0, binding = 7, std430) buffer SampleMaterials { uint sampleMaterial[]; };

// The fragment's material into each of its covered samples' words (shared/sample_material.h). The
// stencil's first-fragment test leaves one fragment per sample, so no word is written twice, and
// an add into the cleared word (agaa.clear) stores the value. Atomic all the same, as every access
// to the AG-buffer here: a plain store would make the synchronisation validation see writes racing
// between draws.
void writeSampleMaterial(uint pixelIndex, uint mask, MaterialSample m) {
    uint words[kSampleMaterialWords] =
        uint[](packSnorm2x16(encodeOctahedral(m.normal)), packUnorm4x8(vec4(srgbEncode(m.albedo), m.metallic)),
               packUnorm2x16(vec2(m.roughness, 0.0)));
    for (uint hw = 0u; hw < 4u; ++hw) {
        if ((mask & (1u << hw)) == 0u) continue;
        uint at = sampleMaterialWord(pixelIndex, agaa.shape.w, inLayer * 4u + hw);
        for (uint w = 0u; w < kSampleMaterialWords; ++w) atomicAdd(sampleMaterial[at + w], words[w]);
    }
}
