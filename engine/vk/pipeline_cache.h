#pragma once
// Pipelines made on first use and kept per typed variant key (STYLE.md: one typed variant key per
// pass, pipelines from a cache keyed by it, as Filament's Variant). A key is a plain struct of the
// choices that select a pipeline, ordered by a defaulted operator<=>; `make` builds the pipeline a
// key stands for. A pass asks get(key) for each draw while it records, never creating one twice.

#include "engine/vk/device.h"

#include <vulkan/vulkan.h>

#include <cstddef>
#include <functional>
#include <map>
#include <utility>

namespace eng::vk {

template <class Key> class PipelineCache {
  public:
    using Make = std::function<VkPipeline(const Key&)>;
    using Destroy = std::function<void(VkPipeline)>;

    PipelineCache(Make make, Destroy destroy) : m_make(std::move(make)), m_destroy(std::move(destroy)) {}
    PipelineCache(const Device& device, Make make)
        : PipelineCache(std::move(make),
                        [d = device.device()](VkPipeline p) { vkDestroyPipeline(d, p, nullptr); }) {}
    ~PipelineCache() { release(); }
    PipelineCache(const PipelineCache&) = delete;
    PipelineCache& operator=(const PipelineCache&) = delete;

    VkPipeline get(const Key& key) {
        auto it = m_pipelines.find(key);
        if (it != m_pipelines.end()) return it->second;
        VkPipeline p = m_make(key); // may throw: nothing is kept then
        m_pipelines.emplace(key, p);
        return p;
    }
    size_t size() const { return m_pipelines.size(); }

    // Destroys every pipeline made (the owner waits for the device first).
    void release() {
        for (const auto& [key, p] : m_pipelines)
            m_destroy(p);
        m_pipelines.clear();
    }

  private:
    Make m_make;
    Destroy m_destroy;
    std::map<Key, VkPipeline> m_pipelines;
};

} // namespace eng::vk
