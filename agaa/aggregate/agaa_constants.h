#pragma once
// Builds the AGAA uniform block (shared/agaa.h): the normal-decoding tables, the clustering
// constants of Equation 1 and the Toksvig reference exponent.

#include "agaa/common/effects.h"
#include "shared/agaa.h"
#include "shared/frame.h"

#include <cstdint>

namespace agaa {

enum class AggregateDebugView : uint32_t { None = 0, Aggregates = 1 };
// Where an aggregate is shaded from: the mean of its samples' view positions (default), or the
// UE4 shortcut (seed 004): its mean depth on the pixel centre's ray.
enum class AggregatePosition : uint32_t { SampleMean = 0, PixelCentre = 1 };
// How an aggregate's normals are filtered (shared/agaa.h layouts, same 20 bytes each): the
// isotropic Toksvig vector of paper section 3.5.2, or the anisotropic SGGX matrix (shared/sggx.h,
// the paper's choice for thin glossy rods) with the two-point tone-mapped resolve.
// Auto: SGGX where the scene has glossy metals (eng::scene::SceneFeatures::glossyMetalMaterials),
// Toksvig elsewhere (its mean shading normal lights diffuse aggregates better: measured in
// agaa/aggregate/README.md).
enum class AggregateNdf : uint32_t { Toksvig = 0, Sggx = 1, Auto = 2 };

struct AggregateSettings {
    uint32_t samples = 8;              // n
    uint32_t aggregates = 2;           // c
    float characteristicLength = 0.1f; // k, metres (paper: 10 cm)
    // t in Equation 1 units: a further aggregate is only created from samples farther than t
    // from every seed. Default measured on the scenegen scenes (agaa/aggregate/README.md).
    float seedThreshold = 0.05f;
    AggregateDebugView debugView = AggregateDebugView::None;
    AggregatePosition position = AggregatePosition::SampleMean;
    AggregateNdf ndf = AggregateNdf::Auto;
    EffectSettings effects; // scene-driven shadows (taps: the footprint filter), alpha-to-coverage, ...
};

// The shared BRDF's GGX alpha range, as kMinGgxAlpha / kMaxGgxAlpha in
// shaders/glsl/common/epsilon.glsl.
inline constexpr float kMinGgxAlpha = 1.0e-3f;
inline constexpr float kMaxGgxAlpha = 0.9f;

// Throws std::invalid_argument naming the setting and its allowed range.
void validate(const AggregateSettings&);

shared::AgaaConstants makeAgaaConstants(const AggregateSettings&, const shared::FrameConstants&,
                                        bool hasEmissive);

} // namespace agaa
