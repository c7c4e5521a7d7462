#include "engine/vk/timestamps.h"

#include "engine/vk/check.h"

namespace eng::vk {

TimestampPool::TimestampPool(const Device& device, uint32_t maxQueries)
    : m_device(device), m_capacity(maxQueries) {
    VkQueryPoolCreateInfo info{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
    info.queryType = VK_QUERY_TYPE_TIMESTAMP;
    info.queryCount = maxQueries;
    VK_CHECK(vkCreateQueryPool(device.device(), &info, nullptr, &m_pool));
    device.setName(VK_OBJECT_TYPE_QUERY_POOL, m_pool, "agaa.timestamps");
    reset();
}

TimestampPool::~TimestampPool() {
    vkDestroyQueryPool(m_device.device(), m_pool, nullptr);
}

void TimestampPool::reset() {
    vkResetQueryPool(m_device.device(), m_pool, 0, m_capacity);
}

std::vector<double> TimestampPool::readPairsMs(uint32_t pairs) const {
    std::vector<double> ms;
    if (pairs == 0) return ms;
    std::vector<uint64_t> ticks(pairs * 2);
    VK_CHECK(vkGetQueryPoolResults(m_device.device(), m_pool, 0, pairs * 2, ticks.size() * sizeof(uint64_t),
                                   ticks.data(), sizeof(uint64_t),
                                   VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT));
    uint32_t bits = m_device.caps().timestampValidBits;
    uint64_t mask = bits >= 64 ? ~0ull : ((1ull << bits) - 1);
    double period = m_device.caps().timestampPeriodNs;
    for (uint32_t i = 0; i < pairs; ++i) {
        uint64_t delta = (ticks[2 * i + 1] - ticks[2 * i]) & mask; // wraps correctly within the valid bits
        ms.push_back(double(delta) * period * 1e-6);
    }
    return ms;
}

double TimestampPool::readSpanMs(uint32_t count) const {
    if (count < 2) return 0.0;
    uint64_t first = 0, last = 0;
    VK_CHECK(vkGetQueryPoolResults(m_device.device(), m_pool, 0, 1, sizeof first, &first, sizeof first,
                                   VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT));
    VK_CHECK(vkGetQueryPoolResults(m_device.device(), m_pool, count - 1, 1, sizeof last, &last, sizeof last,
                                   VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT));
    uint32_t bits = m_device.caps().timestampValidBits;
    uint64_t mask = bits >= 64 ? ~0ull : ((1ull << bits) - 1);
    return double((last - first) & mask) * m_device.caps().timestampPeriodNs * 1e-6;
}

} // namespace eng::vk
