#include "engine/graph/alias_planner.h"

#include <algorithm>
#include <numeric>
#include <stdexcept>
#include <string>

namespace eng::rg {
namespace {

VkDeviceSize alignUp(VkDeviceSize value, VkDeviceSize alignment) {
    return (value + alignment - 1) / alignment * alignment;
}

bool overlapsInTime(const AliasRequest& a, const AliasRequest& b) {
    return a.firstUse <= b.lastUse && b.firstUse <= a.lastUse;
}

void check(const AliasRequest& request, size_t index) {
    const std::string which = "alias planner: request " + std::to_string(index);
    if (request.size == 0) throw std::invalid_argument(which + " has size 0");
    if (request.alignment == 0 || (request.alignment & (request.alignment - 1)) != 0)
        throw std::invalid_argument(which + " has alignment " + std::to_string(request.alignment) +
                                    ", not a power of two");
    if (request.memoryTypeBits == 0) throw std::invalid_argument(which + " accepts no memory type");
    if (request.lastUse < request.firstUse)
        throw std::invalid_argument(which + " ends (" + std::to_string(request.lastUse) +
                                    ") before it starts (" + std::to_string(request.firstUse) + ")");
}

} // namespace

AliasPlan planAliasing(const std::vector<AliasRequest>& requests) {
    for (size_t i = 0; i < requests.size(); ++i)
        check(requests[i], i);
    AliasPlan plan;
    plan.placements.resize(requests.size());
    std::vector<uint32_t> order(requests.size());
    std::iota(order.begin(), order.end(), 0u);
    // Largest first: a block is sized by its first object, so later ones fit in its gaps.
    std::stable_sort(order.begin(), order.end(),
                     [&](uint32_t a, uint32_t b) { return requests[a].size > requests[b].size; });
    std::vector<uint32_t> blockClass;
    std::vector<std::vector<uint32_t>> placedIn; // per block, requests placed so far

    for (uint32_t r : order) {
        const AliasRequest& request = requests[r];
        plan.requestedBytes += request.size;
        bool placed = false;
        for (uint32_t b = 0; b < plan.blocks.size() && !placed; ++b) {
            if (blockClass[b] != request.memoryClass) continue;
            if ((plan.blocks[b].memoryTypeBits & request.memoryTypeBits) == 0) continue;
            // Candidate offsets: the block's start and the end of every object alive meanwhile.
            std::vector<uint32_t> alive;
            std::vector<VkDeviceSize> candidates{0};
            for (uint32_t other : placedIn[b]) {
                if (!overlapsInTime(request, requests[other])) continue;
                alive.push_back(other);
                candidates.push_back(plan.placements[other].offset + requests[other].size);
            }
            std::sort(candidates.begin(), candidates.end());
            for (VkDeviceSize candidate : candidates) {
                const VkDeviceSize offset = alignUp(candidate, request.alignment);
                if (offset + request.size > plan.blocks[b].size) break;
                const bool free = std::none_of(alive.begin(), alive.end(), [&](uint32_t other) {
                    const VkDeviceSize start = plan.placements[other].offset;
                    return offset < start + requests[other].size && start < offset + request.size;
                });
                if (!free) continue;
                plan.placements[r] = {b, offset};
                plan.blocks[b].memoryTypeBits &= request.memoryTypeBits;
                placedIn[b].push_back(r);
                placed = true;
                break;
            }
        }
        if (placed) continue;
        plan.placements[r] = {static_cast<uint32_t>(plan.blocks.size()), 0};
        plan.blocks.push_back({request.size, request.memoryTypeBits});
        blockClass.push_back(request.memoryClass);
        placedIn.push_back({r});
        plan.allocatedBytes += request.size;
    }
    return plan;
}

bool sharesMemory(const AliasPlan& plan, const std::vector<AliasRequest>& requests, uint32_t a, uint32_t b) {
    const AliasPlacement& pa = plan.placements.at(a);
    const AliasPlacement& pb = plan.placements.at(b);
    if (a == b || pa.block != pb.block) return false;
    return pa.offset < pb.offset + requests.at(b).size && pb.offset < pa.offset + requests.at(a).size;
}

} // namespace eng::rg
