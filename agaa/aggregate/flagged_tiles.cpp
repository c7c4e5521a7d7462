#include "agaa/aggregate/flagged_tiles.h"

#include "shared/frame.h"

namespace agaa {

eng::rg::Buffer addFlaggedTileList(eng::rg::Graph& graph, uint32_t width, uint32_t height,
                                   const std::string& name) {
    namespace rg = eng::rg;
    const uint32_t tiles = ((width + shared::kTileSize - 1) / shared::kTileSize) *
                           ((height + shared::kTileSize - 1) / shared::kTileSize);
    struct Clear {
        rg::Buffer list;
    };
    return graph
        .addPass<Clear>(
            name + ".clear", rg::PassKind::Transfer,
            [&](rg::Builder& b, Clear& d) {
                d.list = b.write(b.create(name, {VkDeviceSize(3 + tiles) * 4}), rg::Use::TransferDst);
            },
            [](const rg::Context& ctx, const Clear& d) {
                vkCmdFillBuffer(ctx.cmd(), ctx.buffer(d.list).buffer, 0, 4, 0); // no tile yet
                vkCmdFillBuffer(ctx.cmd(), ctx.buffer(d.list).buffer, 4, 8, 1); // y = z = 1
            })
        .list;
}

} // namespace agaa
