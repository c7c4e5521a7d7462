#include "agaa/aggregate/clustering.h"

#include "shared/clustering.h"

namespace agaa {

PixelClusters clusterPixel(uint32_t x, uint32_t y, const PixelSamples& in,
                           const shared::FrameConstants& frame, const shared::AgaaConstants& agaa) {
    const uint32_t n = agaa.shape.w, c = agaa.shape.x;
    float px[shared::kMaxSamples] = {}, py[shared::kMaxSamples] = {}, pz[shared::kMaxSamples] = {};
    float nx[shared::kMaxSamples] = {}, ny[shared::kMaxSamples] = {}, nz[shared::kMaxSamples] = {};
    bool valid[shared::kMaxSamples] = {};
    uint32_t model[shared::kMaxSamples] = {}; // the prepass has no shading model: all one
    float vx, vy, vz;
    shared::pixelCentreToCamera(x, y, agaa.ndcParams.x, agaa.ndcParams.y, agaa.ndcParams.z, agaa.ndcParams.w,
                                vx, vy, vz);
    for (uint32_t s = 0; s < n; ++s) {
        float d = in.depth[s];
        valid[s] = d > 0.0f;
        if (!valid[s]) continue;
        shared::sampleScaledPosition(x, y, frame.samplePositions[s].x, frame.samplePositions[s].y, d,
                                     agaa.ndcParams.x, agaa.ndcParams.y, agaa.ndcParams.z, agaa.ndcParams.w,
                                     frame.depthParams.x, agaa.clustering.z, agaa.clustering.w,
                                     agaa.clustering.x, px[s], py[s], pz[s]);
        const auto& t = agaa.cosSinTheta[in.theta[s]];
        const auto& p = agaa.cosSinPhi[in.phi[s]];
        shared::decodeFaceNormal(t.x, t.y, p.x, p.y, vx, vy, vz, nx[s], ny[s], nz[s]);
    }
    PixelClusters out;
    uint32_t ids[shared::kMaxSamples] = {};
    out.count = shared::clusterSamples(n, c, agaa.modes.x, agaa.clustering.y, px, py, pz, nx, ny, nz, model,
                                       valid, ids);
    for (uint32_t s = 0; s < shared::kMaxSamples; ++s)
        out.ids[s] = ids[s];
    for (uint32_t w = 0; w < agaa.shape.z; ++w)
        out.words[w] = shared::packMetadataWord(w, n, c, ids);
    return out;
}

ClusterImage clusterImage(uint32_t width, uint32_t height, const std::vector<PixelSamples>& samples,
                          const shared::FrameConstants& frame, const shared::AgaaConstants& agaa) {
    ClusterImage out;
    const uint32_t words = agaa.shape.z;
    out.metadata.resize(size_t(width) * height * words);
    out.counts.resize(size_t(width) * height);
    for (uint32_t y = 0; y < height; ++y)
        for (uint32_t x = 0; x < width; ++x) {
            size_t i = size_t(y) * width + x;
            PixelClusters p = clusterPixel(x, y, samples[i], frame, agaa);
            out.counts[i] = p.count;
            for (uint32_t w = 0; w < words; ++w)
                out.metadata[i * words + w] = p.words[w];
        }
    return out;
}

} // namespace agaa
