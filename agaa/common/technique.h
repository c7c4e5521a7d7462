#pragma once
// The face every anti-aliasing technique shows the host: it adds its passes to
// the host's render graph and hands back the targets. It owns pipelines (which
// outlive frames: lavapipe JIT-compiles each on first use), no window, no swapchain.
//
// Per-frame state and lifetimes (issue 18). addPasses() records; nothing runs until the host
// executes and submits the graph. The only per-frame data a technique writes on the host are its
// uniform constants (AGAA's AgaaConstants, every shadowed method's ShadowConstants), and those go
// into a ring of buffers indexed by FrameInputs::frameSlot (engine/frame/uniform_ring.h). So:
//  - a host that records several views, or several frames, before any of them executes gives each
//    its own frameSlot, e.g. frame-in-flight index x views per frame + view (at most
//    UniformRing::kMaxSlots); two views in one graph with the same slot are refused;
//  - a slot may be recorded again once the fence of the submission that last used it signalled;
//  - everything else a pass uses is either created by the graph (transients, valid while the
//    graph's transients are realised) or imported by the host (FrameInputs' buffers, which the
//    host keeps per frame slot as well, e.g. with agaa/common/frame_inputs.h: the node reads
//    them, it never writes them);
//  - the technique itself (pipelines, samplers, ring) must outlive every submitted graph that
//    holds its passes.
// Threads: a technique is not thread-safe. One thread at a time calls addPasses(); recording a
// graph that holds its passes (Graph::execute) may happen on another thread after addPasses()
// returned, as execute callbacks only read state that no later addPasses() changes.

#include "agaa/common/effects.h"
#include "agaa/common/program_overrides.h"
#include "engine/graph/graph.h"
#include "shared/frame.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace agaa {

class GeometryDrawer;

// A host's own shadow maps, in place of the module's shadow pass (agaa/common/shadow_map.h): a
// D32_SFLOAT 2D array of at least 2 layers, one sample, with a depth-aspect sampled view
// (PhysicalTexture::sampledView) and SAMPLED usage, layer l the map of the light
// constants.lightIndex[l]; and the shared::ShadowConstants the lighting looks them up with (a
// uniform buffer; ShadowMapPass::makeConstants fits them as the module does). `initial`: the
// map's state when the frame begins (e.g. Use::DepthStencilWrite after the host drew it).
struct HostShadowMaps {
    eng::rg::PhysicalTexture map;
    eng::rg::PhysicalBuffer constants;
    std::optional<eng::rg::Use> initial;
};

// Inputs every technique reads; the host imports these buffers into its graph.
struct FrameInputs {
    // The host's drawer for every raster pass (agaa/common/raster_pass.h); null: each pass draws
    // the GpuScene the technique was created with (TechniqueContent) with this project's materials
    // (agaa::SceneDrawer). It must outlive the recording of the graph.
    GeometryDrawer* geometry = nullptr;
    // The environment the lighting passes bind (agaa/common/effects.h); null: the GpuScene's the
    // technique was created with. Must outlive the recording of the graph.
    const EnvironmentBindings* environment = nullptr;
    // The host's shadow maps (read where the scene has shadowed lights); null: the module draws its
    // own. Must outlive the recording of the graph.
    const HostShadowMaps* shadowMaps = nullptr;
    const shared::FrameConstants* constants = nullptr; // the values behind frameConstants
    eng::rg::Buffer frameConstants;                    // shared::FrameConstants, uniform
    eng::rg::Buffer lights;                            // shared::GpuLight[], storage
    uint32_t width = 0;
    uint32_t height = 0;
    // Which slot of the technique's per-frame ring this recording writes its constants into
    // (see the top of this file). 0 for a host that waits for each frame before the next.
    uint32_t frameSlot = 0;
};

// Outputs every technique produces, with the same meaning (DESIGN section 6).
struct FrameTargets {
    eng::rg::Texture hdr; // RGBA32F linear radiance, box-resolved
    eng::rg::Texture
        display; // RGBA32F: each shading event tone-mapped, weighted by its sample fraction, summed
    eng::rg::Texture shadingEvents; // R32_UINT: shading events per pixel
    // R32_UINT, only from methods that drop coverage (SBAA): covered samples per pixel whose
    // surface was not kept, so their coverage is missing from the resolve. Invalid otherwise.
    eng::rg::Texture lostSamples;
    // The per-sample visibility depth, reversed Z (1 at znear, 0 = sky; common/depth.glsl): 4x
    // with n/4 layers for n >= 4, one sample for n = 1; D32, with stencil on AGAA's accumulate
    // path. For writing a host's depth target (agaa/common/host_targets.h).
    eng::rg::Texture depth;
    // R32_UINT, only from AGAA with a shading-rate tolerance (AggregateSettings::tolerance): a bit
    // per sample shaded one by one (all n where the whole pixel was), 0 where the pixel's
    // aggregates alone lit it. Invalid otherwise.
    eng::rg::Texture perSampleShaded;
};

// A frame's drawer: the host's, else `sceneDrawer` (present when the technique was created with a
// GpuScene). Throws std::invalid_argument naming FrameInputs::geometry when there is neither.
GeometryDrawer& frameDrawer(const FrameInputs& in, GeometryDrawer* sceneDrawer, const std::string& pass);
// A frame's environment: the host's, else `scene`'s; throws naming FrameInputs::environment when
// there is neither.
EnvironmentBindings frameEnvironment(const FrameInputs& in, const eng::frame::GpuScene* scene,
                                     const std::string& technique);

class Technique {
  public:
    virtual ~Technique() = default;
    virtual std::string name() const = 0;
    // Visibility samples per pixel this technique rasterises (selects the sample pattern).
    virtual uint32_t samples() const = 0;
    virtual FrameTargets addPasses(eng::rg::Graph& graph, const FrameInputs& inputs) = 0;
    // Resource names that are this technique's own per-pixel storage (for bytes_per_pixel).
    virtual bool isStorage(const std::string& resourceName) const = 0;
    // Which part of the storage a resource is, for the bytes-per-pixel split:
    // "per-sample", "per-aggregate", "metadata" or "transient".
    virtual std::string storageCategory(const std::string& resourceName) const {
        return isStorage(resourceName) ? "per-sample" : "transient";
    }
    // The shader/pass variants this technique chose from the scene's features, each with its
    // cause (agaa/common/effects.h), for the stats and the graph dump.
    virtual std::vector<VariantChoice> variants() const { return {}; }
    // Temporal methods (agaa/temporal/temporal_aa.h) carry a history from one frame to the next:
    // every frame must be recorded anew (addPasses once per frame, in order), with the sub-pixel
    // jitter subpixelJitter() gives for it in eng::frame::ViewSettings::jitter. The others'
    // recorded graph may be replayed.
    virtual bool temporal() const { return false; }
    // The jitter of the next frame addPasses records, in pixels (each component in [-0.5, 0.5]).
    virtual glm::vec2 subpixelJitter() const { return {0.0f, 0.0f}; }
    // A camera cut: a temporal method forgets its history, and its next frame is its first again
    // (the same jitter sequence from the start).
    virtual void resetHistory() {}
};

} // namespace agaa
