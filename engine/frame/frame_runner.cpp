#include "engine/frame/frame_runner.h"

#include <stdexcept>

namespace eng::frame {

constexpr uint32_t kMaxTimedPasses = 128;

FrameRunner::FrameRunner(vk::Device& device)
    : m_device(device), m_pool(device), m_timestamps(device, 2 * kMaxTimedPasses) {}

FrameTiming FrameRunner::run(rg::Graph& graph) {
    if (!graph.isCompiled()) graph.compile();
    uint32_t queries = graph.timestampCount();
    if (queries > m_timestamps.capacity())
        throw std::logic_error("frame has more than " + std::to_string(kMaxTimedPasses) + " passes");
    m_pool.clearUsage();
    m_timestamps.reset();
    m_device.submitAndWait([&](VkCommandBuffer cmd) {
        rg::Graph::ExecuteInfo info;
        info.cmd = cmd;
        info.allocator = &m_pool;
        info.queryPool = m_timestamps.pool();
        info.beginLabel = m_device.beginLabel();
        info.endLabel = m_device.endLabel();
        graph.execute(info);
    });
    graph.releaseTransients();

    FrameTiming timing;
    std::vector<std::string> names = graph.executedPassNames();
    std::vector<double> ms = m_timestamps.readPairsMs(uint32_t(names.size()));
    for (size_t i = 0; i < names.size(); ++i)
        timing.passes.push_back({names[i], ms[i]});
    timing.frameMs = m_timestamps.readSpanMs(uint32_t(2 * names.size()));
    return timing;
}

} // namespace eng::frame
