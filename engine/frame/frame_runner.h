#pragma once
// Runs one compiled render graph on the device: records it into a command
// buffer with a timestamp pair and a debug label around every pass, submits,
// waits, and returns the GPU time of each pass.

#include "engine/frame/transient_pool.h"
#include "engine/graph/graph.h"
#include "engine/vk/device.h"
#include "engine/vk/timestamps.h"

#include <string>
#include <vector>

namespace eng::frame {

struct PassTiming {
    std::string name;
    double gpuMs = 0.0;
};

struct FrameTiming {
    std::vector<PassTiming> passes; // execution order
    double frameMs = 0.0;           // first pass's start to last pass's end
};

class FrameRunner {
  public:
    explicit FrameRunner(vk::Device& device);
    // Compiles the graph if needed, executes it, waits for the GPU. Transients stay realised in
    // the pool (and are reused by the next graph with the same resources).
    FrameTiming run(rg::Graph& graph);
    TransientPool& pool() { return m_pool; }
    vk::Device& device() { return m_device; }

  private:
    vk::Device& m_device;
    TransientPool m_pool;
    vk::TimestampPool m_timestamps;
};

} // namespace eng::frame
