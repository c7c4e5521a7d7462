#pragma once
// A test-only pass that copies what a peer's kernel reads per sample into a buffer, so its CPU
// twin runs on the same inputs (MSAA images cannot be copied to buffers directly). The kernel is a
// test kernel (agaa_test_shaders): SBAA's selection inputs, streaming's recorded fragments,
// Simple/Complex's classification inputs. It reads the frame constants at binding 0 and the
// textures it is given, writes one buffer, and runs in 8x8 groups over the frame.

#include "agaa/common/technique.h"
#include "engine/vk/device.h"
#include "engine/vk/pipeline.h"

#include <span>
#include <string>
#include <utility>
#include <vector>

namespace agaa::test {

class SampleInputsExport {
  public:
    SampleInputsExport(eng::vk::Device& device, std::span<const uint32_t> kernel, std::string name);
    ~SampleInputsExport();
    SampleInputsExport(const SampleInputsExport&) = delete;
    SampleInputsExport& operator=(const SampleInputsExport&) = delete;

    // `textures`: (binding, texture) pairs, each sampled through a nearest-neighbour sampler.
    void add(eng::rg::Graph& graph, const FrameInputs& inputs,
             const std::vector<std::pair<uint32_t, eng::rg::Texture>>& textures, uint32_t targetBinding,
             eng::rg::Buffer target);

  private:
    eng::vk::Device& m_device;
    std::string m_name;
    eng::vk::PipelineLayout m_layout;
    VkPipeline m_pipeline = VK_NULL_HANDLE;
    VkSampler m_sampler = VK_NULL_HANDLE;
};

// The three peers' kernels.
SampleInputsExport sbaaSelectionInputs(eng::vk::Device& device);
SampleInputsExport streamingFragments(eng::vk::Device& device);
SampleInputsExport simpleComplexClassificationInputs(eng::vk::Device& device);

} // namespace agaa::test
