#pragma once
// A timestamp query pool giving GPU time per pass: the graph writes a pair of
// timestamps around each executed pass; read() turns them into milliseconds.

#include "engine/vk/device.h"

#include <vector>

namespace eng::vk {

class TimestampPool {
  public:
    TimestampPool(const Device& device, uint32_t maxQueries);
    ~TimestampPool();
    TimestampPool(const TimestampPool&) = delete;
    TimestampPool& operator=(const TimestampPool&) = delete;

    VkQueryPool pool() const { return m_pool; }
    uint32_t capacity() const { return m_capacity; }
    void reset(); // host reset of every query (hostQueryReset), before recording
    // Milliseconds between query 2i and 2i+1 for i < pairs; waits for the results.
    std::vector<double> readPairsMs(uint32_t pairs) const;
    // Milliseconds from query 0 to query count-1.
    double readSpanMs(uint32_t count) const;

  private:
    const Device& m_device;
    VkQueryPool m_pool = VK_NULL_HANDLE;
    uint32_t m_capacity = 0;
};

} // namespace eng::vk
