// Step 3's two schedules (specialisation id 7, agaa/aggregate/agaa_constants.h AggregateShading).
// Both call shadeAggregate on the same values, so their images are bit-identical (tested).
//  - compacted (the default for c >= 2 on GPUs): every further aggregate of the tile (a >= 1) is
//    appended to a per-tile list in shared memory and the list is shaded kListRound entries at a
//    time, one entry per invocation, so every SIMD lane is busy whatever the clustering decided
//    (the per-pixel schedule pays for the pixel with the most aggregates in each SIMD group).
//    Aggregate 0 of every covered pixel is shaded in registers after the rounds;
//  - registers: each invocation shades its own pixel's aggregates (cheaper when c = 1, where a
//    pixel holds at most one aggregate and the list only adds shared-memory traffic).
const uint kTilePixels = kTileSize * kTileSize;
// Entries of the per-tile list shaded per round: one per invocation. c = 4 can append up to
// 4 x 256; the list is then shaded in up to 4 rounds through the same 256-entry storage, which
// keeps the tile's shared memory at 26.5 KB (lavapipe offers 32 KB).
const uint kListRound = kTilePixels;

// One round of the per-tile list, struct-of-arrays. Inputs, written by the aggregate's pixel:
//   sPosition  xyz view-space shading position, w depth standard deviation (shadow footprint)
//   sNormal    xyz shading normal, w roughness (SGGX: the square root of the material alpha)
//   sAlbedo    rgb albedo, a metallic
//   sTangent   xyz tangent (SGGX), w alphas.x;  sBitangent: xyz bitangent (SGGX), w alphas.y
//   sOwner     tile pixel index | aggregate id << 8 | the aggregate's sample count << 10
//   sSpread    x spread, y environment roughness
//   sScreenSpread  the covariance (xx, xy, yy) of its samples' sub-pixel positions, pixel^2
// Outputs, written in place by the invocation that shades the entry: sPosition.xyz radiance,
// sNormal.xyz specular part, sAlbedo.xyz its variance over the aggregate's samples.
shared vec4 sPosition[kListRound];
shared vec4 sNormal[kListRound];
shared vec4 sAlbedo[kListRound];
shared vec4 sTangent[kListRound];
shared vec4 sBitangent[kListRound];
shared uint sOwner[kListRound];
shared vec2 sSpread[kListRound];
shared vec3 sScreenSpread[kListRound];
shared uint sEntryCount;

// Before the tile's first barrier (tileBoundsBegin), which orders it before the appends.
void tileListBegin() {
    if (kCompactShading != 0u && gl_LocalInvocationIndex == 0u) sEntryCount = 0u;
}

// The slots of this pixel's further aggregates in the tile's list.
uint tileListAppend(uint presentCount) {
    uint extraCount = presentCount - (aggregates[0].present ? 1u : 0u);
    return kCompactShading != 0u && extraCount > 0u ? atomicAdd(sEntryCount, extraCount) : 0u;
}

void storeListEntry(uint e, Aggregate ag) {
    sPosition[e] = vec4(ag.position, ag.depthSigma);
    sNormal[e] = vec4(ag.surface.normal, ag.surface.roughness);
    sAlbedo[e] = vec4(ag.surface.albedo, ag.surface.metallic);
    sTangent[e] = vec4(ag.tangent, ag.alphas.x);
    sBitangent[e] = vec4(ag.bitangent, ag.alphas.y);
    sOwner[e] = gl_LocalInvocationIndex | (ag.id << 8u) | (ag.samples << 10u);
    sSpread[e] = vec2(ag.spread, ag.environmentRoughness);
    sScreenSpread[e] = ag.screenSpread;
}

Aggregate loadListEntry(uint e) {
    Aggregate ag;
    uint owner = sOwner[e];
    uint ownerIndex = owner & 0xFFu;
    ag.pixel = ivec2(gl_WorkGroupID.xy * kTileSize + uvec2(ownerIndex % kTileSize, ownerIndex / kTileSize));
    ag.pixelIndex = uint(ag.pixel.y * int(frame.extent.x) + ag.pixel.x);
    ag.id = (owner >> 8u) & 3u;
    ag.samples = owner >> 10u;
    ag.surface.normal = sNormal[e].xyz;
    ag.surface.roughness = sNormal[e].w;
    ag.surface.albedo = sAlbedo[e].rgb;
    ag.surface.metallic = sAlbedo[e].a;
    ag.tangent = sTangent[e].xyz;
    ag.bitangent = sBitangent[e].xyz;
    ag.alphas = vec2(sTangent[e].w, sBitangent[e].w);
    ag.spread = sSpread[e].x;
    ag.environmentRoughness = sSpread[e].y;
    ag.position = sPosition[e].xyz;
    ag.depthSigma = sPosition[e].w;
    ag.screenSpread = sScreenSpread[e];
    ag.present = true;
    return ag;
}

// The compacted schedule. The slots are taken in whatever order the appends ran; an entry's
// result depends only on its own values and the tile's lights, so the image does not depend on
// that order. Every invocation runs the same rounds (sEntryCount is uniform over the workgroup).
void shadeTileList(uint firstEntry) {
    uint entries = sEntryCount;
    for (uint listRound = 0u; listRound * kListRound < entries; ++listRound) {
        uint lo = listRound * kListRound;
        uint slot = firstEntry;
        for (uint a = 1u; a < kAggregates; ++a) {
            if (!aggregates[a].present) continue;
            if (slot >= lo && slot < lo + kListRound) storeListEntry(slot - lo, aggregates[a]);
            slot += 1u;
        }
        barrier();
        uint self = gl_LocalInvocationIndex;
        if (self < entries - lo) {
            Aggregate ag = loadListEntry(self);
            Shading shading;
            OffLayerShading unused; // no off-layer samples beyond aggregate 0
            shadeAggregate(ag, noOffLayer(ag), shading, unused);
            sPosition[self].xyz = shading.radiance;
            sNormal[self].xyz = shading.specular;
            sAlbedo[self].xyz = shading.specularVariance;
        }
        barrier();
        slot = firstEntry;
        for (uint a = 1u; a < kAggregates; ++a) {
            if (!aggregates[a].present) continue;
            if (slot >= lo && slot < lo + kListRound) {
                uint e = slot - lo;
                shaded[a].radiance = sPosition[e].xyz;
                shaded[a].specular = sNormal[e].xyz;
                shaded[a].specularVariance = sAlbedo[e].xyz;
            }
            slot += 1u;
        }
        barrier(); // the next round overwrites the list
    }
}
