#pragma once
// An environment's device copy (issue 16; engine/frame/environment_maps.h), bound by every lighting
// pass: its pre-filtered specular levels as an RGBA16F 2D array (one layer per level, u repeats,
// v clamps), its constants (uniform, shared::EnvironmentConstants) and the split sum's BRDF table
// (integrateDfgTable, RG16F, clamped). Without an environment it holds the stand-in: a 1x1 black
// array and constants with params.x = 0, which lighting skips by specialisation. Our GpuScene
// holds one; a host with its own content makes its own (agaa::environmentBindings). Uploaded when
// constructed; the images are then in SHADER_READ_ONLY_OPTIMAL for good.

#include "engine/scene/environment.h"
#include "engine/vk/device.h"
#include "engine/vk/resources.h"

namespace eng::frame {

class GpuEnvironment {
  public:
    // `environment`: null or empty for the stand-in.
    GpuEnvironment(vk::Device& device, const scene::Environment* environment);
    ~GpuEnvironment();
    GpuEnvironment(const GpuEnvironment&) = delete;
    GpuEnvironment& operator=(const GpuEnvironment&) = delete;

    bool present() const { return m_present; }
    VkImageView view() const { return m_prefiltered.view; }
    VkSampler sampler() const { return m_sampler; }
    VkImageView dfgView() const { return m_dfg.view; }
    VkSampler dfgSampler() const { return m_dfgSampler; }
    const vk::Buffer& constants() const { return m_constants; }
    VkDeviceSize bytes() const { return m_prefiltered.bytes + m_dfg.bytes; }

  private:
    void release(); // the destructor's work, also for a constructor that throws

    vk::Device& m_device;
    bool m_present = false;
    vk::Buffer m_constants;
    vk::Image m_prefiltered, m_dfg;
    VkSampler m_sampler = VK_NULL_HANDLE, m_dfgSampler = VK_NULL_HANDLE;
};

} // namespace eng::frame
