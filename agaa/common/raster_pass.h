#pragma once
// The geometry and material contract (issue 50; docs/decisions/embedding.md): how a method's raster
// passes draw a host's own geometry with the host's own material shaders.
//
// A raster pass describes itself as a RasterPass: the output its fragment shader must produce,
// its attachments' formats and sample count, how many layers it draws (the layered 4x emulation,
// or one shadow map per light) and the descriptor set 0 the module reserves. The pass begins the
// rendering (attachments, clears, viewport and scissor: the render graph owns them) and hands the
// recording to a GeometryDrawer, which owns the pipelines: it binds them, lets the module push
// set 0 through its own pipeline layout, binds its own sets 1.. and push constants, and draws.
//
// Our scene is one client: agaa::SceneDrawer (agaa/common/scene_drawer.h) draws an
// eng::frame::GpuScene with this project's material shaders, and every technique uses it when the
// host gives no drawer (FrameInputs::geometry).

#include "engine/vk/pipeline.h"

#include <vulkan/vulkan.h>

#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace agaa {

// What the fragment shader of a raster pass writes, location by location (the formats are in
// RasterPass::colorFormats). Draw instance i renders into layer i (gl_Layer = gl_InstanceIndex);
// the camera's passes place it with common/scene_vertex.glsl's sceneClipPosition (the layer's
// sample offset) from set 0 binding 0, shared::FrameConstants.
enum class RasterOutput : uint32_t {
    // The per-sample G-buffer (agaa/common/sample_gbuffer.h): 0 the shading normal, octahedral in
    // view space, and the coverage alpha in w; 1 albedo sRGB-encoded by the shader, metallic in a;
    // 2 emissive radiance and roughness.
    SampleGBuffer,
    // The same and 3: the scene-wide triangle number + 1 as an exact float (0 = nothing).
    SampleGBufferPrimitive,
    // SBAA's visibility prepass: 0 the geometric normal (octahedral, RG8 unorm), 1 as above's 3.
    SurfaceVisibility,
    // SBAA's second geometry pass: no colour; the material goes into the per-surface records
    // (set 0 binding 2, shared/sbaa.h) of the surfaces the fragment's primitive represents
    // (raster/surface_fill_output.glsl), under the prepass depth, read-only, EQUAL.
    SurfaceFill,
    // Depth only, from the light: set 0 binding 0 is shared::ShadowConstants, instance l is
    // seen through relativeToShadow[l]. Masked materials discard below their cutoff.
    ShadowDepth,
    // AGAA's visibility prepass: 0 the face normal as two 8-bit angles about the view ray, coverage
    // in w (raster/aggregate_visibility_output.glsl); depth written, stencil cleared for the
    // accumulation's first-fragment test.
    AggregateVisibility,
    // AGAA's accumulation kernel: the fragment's material added into its pixel's aggregates
    // (raster/aggregate_accumulation_output.glsl); 0 the per-sample emissive target when the
    // scene emits (AGAA_EMISSIVE). Depth EQUAL without writes, the stencil's first-fragment test.
    AggregateAccumulation,
};
const char* rasterOutputName(RasterOutput output);

struct RasterPass {
    std::string name; // "<technique>.gbuffer", "<technique>.shadow": for the drawer's object names
    RasterOutput output = RasterOutput::SampleGBuffer;
    std::vector<VkFormat> colorFormats; // by location
    VkFormat depthFormat = VK_FORMAT_UNDEFINED;
    VkCompareOp depthCompare = VK_COMPARE_OP_GREATER; // the camera's passes: reversed Z
    bool depthWrite = true;
    VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT; // per layer
    uint32_t layers = 1;                                   // instances per draw
    bool sampleRateShading = false;                        // minSampleShading 1
    bool bothFaces = false; // cull nothing, whatever a material says (shadow casters)
    bool stencilTest = false;
    VkStencilOpState stencil{}; // front and back
    // Set 0 of every pipeline the drawer binds: a push-descriptor set with these bindings, which
    // the module pushes (PushModuleSet). The drawer's own sets are 1 and above.
    std::vector<eng::vk::Binding> moduleSet;
    // The module's specialisation constants for its includes (ids in shaders/glsl/shared/
    // specialization.h), to add to the drawer's own.
    eng::vk::Specialization specialization;
    // The macros the module's include is built with for this pass (e.g. AGAA_EMISSIVE,
    // AGAA_INT64, AGAA_SUBGROUP): a drawer compiles its shader once per set it meets.
    std::vector<std::string> defines;
    bool defined(std::string_view macro) const;
    bool operator==(const RasterPass& other) const;
};

// The fixed-function state `pass` fixes, for a drawer that builds its pipelines with
// eng::vk::createGraphicsPipeline: attachments' formats, samples, sample-rate shading, depth and
// stencil, and culling (none for a two-sided material or RasterPass::bothFaces). The drawer adds
// its shaders, layout, vertex input, specialisation (with pass.specialization) and alpha-to-coverage.
eng::vk::GraphicsPipelineDesc rasterPipelineState(const RasterPass& pass, bool twoSided);

// Pushes set 0 through `layout`, a pipeline layout whose set 0 was made from RasterPass::moduleSet.
using PushModuleSet = std::function<void(VkCommandBuffer cmd, VkPipelineLayout layout)>;

class GeometryDrawer {
  public:
    virtual ~GeometryDrawer() = default;
    // When the pass is added to a frame, before anything records: make what recordDraws binds.
    // A pass's description is the key: the same RasterPass again needs nothing new.
    virtual void prepare(const RasterPass& pass) = 0;
    // Inside the pass's rendering: bind a pipeline for `pass`, call pushModuleSet with its layout
    // (again after binding one with another layout), bind the drawer's own sets and draw every
    // draw with pass.layers instances. Called from the graph's recording (any thread, after
    // prepare returned for this pass).
    virtual void recordDraws(VkCommandBuffer cmd, const RasterPass& pass,
                             const PushModuleSet& pushModuleSet) const = 0;
};

} // namespace agaa
