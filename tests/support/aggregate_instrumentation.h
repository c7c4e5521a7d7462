#pragma once
// Test-only passes that look inside AGAA's frame. They add their own nodes to the frame's graph
// after AggregateAA::addPasses (RenderRequest::extraPasses), read the technique's resources(), and
// run test builds of its shaders from the tests' own SPIR-V library (agaa_test_shaders): nothing
// here is in the shipping class, its shaders or its layouts.

#include "agaa/aggregate/aggregate.h"
#include "agaa/common/scene_drawer.h"
#include "engine/vk/pipeline.h"
#include "engine/vk/resources.h"

#include <memory>
#include <vector>

namespace agaa::test {

// Copies what the clustering kernel read for each sample on the accumulate path (uvec2 per
// sample: the depth's bits as texelFetch returns them, theta | phi << 8) into `host`
// (pixels * n * 8 bytes), so that a CPU reference clusters exactly the same inputs
// (shaders/glsl/tests/agaa_clustering_inputs.comp). One object per device; add() once per frame.
class ClusteringInputReadback {
  public:
    explicit ClusteringInputReadback(eng::vk::Device& device);
    ~ClusteringInputReadback();
    ClusteringInputReadback(const ClusteringInputReadback&) = delete;
    ClusteringInputReadback& operator=(const ClusteringInputReadback&) = delete;

    void add(eng::rg::Graph& graph, const AggregateAA& aggregate, const FrameInputs& inputs,
             const eng::vk::Buffer& host);

  private:
    eng::vk::Device& m_device;
    eng::vk::PipelineLayout m_layout;
    VkPipeline m_pipeline = VK_NULL_HANDLE;
    VkSampler m_sampler = VK_NULL_HANDLE;
};

inline constexpr uint32_t kExportRecordFloats = 16; // tests/agaa_lighting_export.comp exportRecord

// The test build of AGAA's lighting pass (shaders/glsl/tests/agaa_lighting_export.comp), run
// beside the shipping one on the same inputs with the same specialisation: it lights the frame
// again into scratch images and exports what its step 1 read and built into `host`, a buffer of
// pixels * (n + c) * kExportRecordFloats floats: sample s of pixel p at p * n + s, then aggregate a
// at pixels * n + p * c + a. The samples path without emissive or shadows only (the test build
// has neither); add() says so otherwise.
class AggregateExportPass {
  public:
    explicit AggregateExportPass(eng::vk::Device& device);
    ~AggregateExportPass();
    AggregateExportPass(const AggregateExportPass&) = delete;
    AggregateExportPass& operator=(const AggregateExportPass&) = delete;

    void add(eng::rg::Graph& graph, const AggregateAA& aggregate, const FrameInputs& inputs,
             const eng::vk::Buffer& host);
    eng::vk::Device& device() const { return m_device; }

  private:
    eng::vk::Device& m_device;
    eng::vk::PipelineLayout m_layout;
    VkSampler m_sampler = VK_NULL_HANDLE;
    // One pipeline per specialisation met (a test may export from several techniques).
    std::vector<std::pair<std::vector<std::pair<uint32_t, uint32_t>>, VkPipeline>> m_pipelines;
};

// The fragments the accumulate path's generation pass accumulated in the central 16x16 pixels
// (shaders/glsl/agaa/generation.frag kRecordWindow), recorded by the pass's test build
// (shaders/glsl/tests/agaa_generation_record.frag) drawn again over the generation's depth and
// stencil: the stencil the shipping pass left at 1 on every sample it took a fragment for lets
// the same first fragment per sample through once more. Into `host`: an 8-byte header {count,
// capacity}, the caller setting the capacity, then 3 + kQuantizedFields + 8 words per fragment
// (pixel, layer, mask, the quantised fields, then as float bits the material's normal xyz,
// roughness, albedo rgb, metallic). Scenes without emissive materials only.
class FragmentRecordPass {
  public:
    explicit FragmentRecordPass(eng::vk::Device& device);
    ~FragmentRecordPass();
    FragmentRecordPass(const FragmentRecordPass&) = delete;
    FragmentRecordPass& operator=(const FragmentRecordPass&) = delete;

    void add(eng::rg::Graph& graph, const AggregateAA& aggregate, const FrameInputs& inputs,
             const eng::vk::Buffer& host);

  private:
    eng::vk::Device& m_device;
    std::vector<std::unique_ptr<SceneDrawer>> m_drawers; // made per add(): each scene its own
};

// A host buffer for `capacity` fragment records of `recordWords` words each (FragmentRecordPass's
// target: the count, the capacity, then the records), its capacity set.
eng::vk::Buffer createFragmentRecords(eng::vk::Device& device, uint32_t capacity, uint32_t recordWords);

} // namespace agaa::test
