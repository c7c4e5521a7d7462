#pragma once
// Ghosting along a camera path (issue 51): a temporal method's error on the pixels the frame
// before did not see. Its history there is wrong (another surface's colour, or none), so what it
// shows until the history refills is its ghost; a method without history is measured on the same
// pixels for comparison.
//
// Which pixels: temporal AA's motion view (`--method taa --debug motion`, shared/temporal.h
// TemporalParams::blend.w) gives, per pixel of frame t, where its centre's surface point lay in
// frame t - 1 and how far it was from that camera; frame t - 1's own motion view gives the
// distance of what that camera did see there. The point was seen when the two agree within
// kDisocclusionDistanceTolerance at the texel the reprojected position falls in or one of its
// eight neighbours (the neighbourhood the resolve clips to), and unseen when they disagree
// everywhere (an occluder stood in front of it), or it fell outside the frame. The sky is seen
// where sky was. The neighbourhood, not the one texel, because one sample a pixel misses thin
// geometry at random: under a pure camera rotation, which hides nothing, the chain-link at 64x64
// has 20 % of its pixels' points missing from the nearest texel, 7 % from the 2x2 bilinear
// footprint and 1.1 % from the 3x3 (tests/gpu/test_temporal_aa.cpp, TemporalRotation).

#include "engine/io/image.h"

#include <cstdint>
#include <vector>

namespace agaa::bench {

// Two distances along the camera's axis name the same surface point when they differ by less
// than this fraction of the point's distance: 2 % absorbs the depth buffer's quantisation and the
// texel-to-centre offset of a sloped surface; an occluder closer than 2 % to what it hides leaves
// a ghost too faint to matter.
inline constexpr float kDisocclusionDistanceTolerance = 0.02f;

// One byte a pixel, row-major, 1 where frame t's pixel was not seen by frame t - 1.
// `motion` is frame t's motion-view HDR image (x, y: the reprojected position in pixels; z: 1 when
// it falls inside the previous frame; w: the point's distance from the previous camera, 0 for the
// sky); `previousDistance` is frame t - 1's motion-view display (r: the distance of its pixel's
// centre point, 0 for the sky). Throws eng::io::IoError as the metrics do (engine/io/metrics.h:
// sizes that differ, an empty image, a non-finite value).
std::vector<uint8_t> disoccludedPixels(const eng::io::ImageF& motion,
                                       const eng::io::ImageF& previousDistance);

// The display RMSE over R, G, B of the masked pixels of every frame pair together (frames[t]
// against truths[t] where masks[t] is 1), and how many pixels that was. Frame 0 carries an empty
// mask (nothing came before it). NaN-free: 0 pixels gives rmse 0.
struct MaskedError {
    double rmse = 0.0;
    uint64_t pixels = 0;
};
MaskedError maskedError(const std::vector<eng::io::ImageF>& frames,
                        const std::vector<eng::io::ImageF>& truths,
                        const std::vector<std::vector<uint8_t>>& masks);

} // namespace agaa::bench
