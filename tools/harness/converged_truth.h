#pragma once
// The converged ground truth every accuracy figure is measured against (DESIGN section 7).
//
// Per-sample shading at the same n, or at n = 32, is not a truth on the content AGAA is for: a
// glossy sub-pixel highlight lands on a few of 32 samples or on none, and a thin-gold scene's
// image mean moves 4x between n = 8 and n = 32. The truth therefore supersamples in space: the
// reference at n = 32, with materials shaded at sample rate, renders the view at k times its
// width and height, and each k x k block is averaged. Two resolves come back, as every method's:
// display (each sample tone-mapped, then averaged) and linear radiance.
//
// Memory stays one frame's at any k: the k^2-times-larger image is rendered as k^2 tiles of the
// output's own size (eng::frame::ViewTile), each accumulated into the output and released.
//
// Every truth carries an estimate of its own error. Its sub-pixel grid is split in two halves
// like a checkerboard (sub-pixel (u, v) of a pixel in half (u + v) mod 2), each an independent
// truth at half the rate; with errors e_A, e_B of equal size and independent, the full truth's
// error is |e_A + e_B| / 2 ~ RMSE(A - B) / 2 (display RMSE on sRGB-encoded values, the metric of
// every figure). A difference between two methods' errors below that is not a measured one.
//
// The linear image mean, the energy figure, has an estimate of its own: the k^2 sub-pixel positions
// (u, v) each make a truth at n samples a pixel on their own, so their images' means are k^2 draws
// of the mean, and the full truth's is off by about their standard deviation over k. Treating the
// stratified sub-pixels as independent draws overstates it a little, the conservative side. On the
// glossy sub-pixel scenes a handful of samples carry the mean, and this says how far the truth's
// own moves with them.
//
// Truths are cached on disk (TruthCache), keyed by a hash of the scene, the view, the lights, the
// exposure, the truth's own settings and the program's binary, so a sweep pays for each once.

#include "tools/harness/frame_renderer.h"

#include "engine/io/image.h"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace agaa {

struct TruthSettings {
    uint32_t supersampling = 4; // k: k x k sub-pixel tiles, each at `samples` (k^2 n samples a pixel)
    uint32_t samples = 32;      // per sub-pixel; the reference's highest rate
};

inline constexpr uint32_t kMaxTruthSupersampling = 16;

// Throws std::invalid_argument naming the field and its range.
void validate(const TruthSettings& settings);

struct ConvergedTruth {
    TruthSettings settings;
    float exposure = 1.0f;
    eng::io::ImageF display; // linear display values in [0, 1] (sRGB-encode for metrics and PNG)
    eng::io::ImageF hdr;     // linear radiance
    // The two checkerboard halves' display images (linear, as `display`).
    eng::io::ImageF halves[2];
    // Display RMSE (sRGB-encoded) of `display` against the limit, estimated as RMSE(A, B) / 2.
    double errorEstimate = 0.0;
    double meanLuminance = 0.0; // linear image mean of hdr (Rec. 709 luma), for energy checks
    // The error of meanLuminance, estimated from the k^2 sub-pixel images' own means: their sample
    // standard deviation over k (infinite for k = 1, where nothing measures it).
    double meanErrorEstimate = 0.0;
    bool fromCache = false;
    std::string key; // the cache key's hash, hex
};

// Linear image mean of Rec. 709 luma (0.2126 R + 0.7152 G + 0.0722 B): the energy figure every
// comparison with the truth's meanLuminance uses. 0 for an empty image.
double meanLuminance(const eng::io::ImageF& hdr);

// Error estimate from two halves: display RMSE between their sRGB encodings, halved. Throws
// eng::io::IoError for images of different sizes or with NaN (as the metrics do).
double truthErrorEstimate(const eng::io::ImageF& halfA, const eng::io::ImageF& halfB);

// The error of a truth's linear mean from its sub-pixel images' own means: their sample standard
// deviation over the square root of their count; infinite for fewer than two.
double truthMeanErrorEstimate(const std::vector<double>& subPixelMeans);

// Accumulates tiles of a k-times-larger image into the output: what renderConvergedTruth does with
// the frames it renders, separate so that it is tested without a device.
class TruthAccumulator {
  public:
    TruthAccumulator(uint32_t width, uint32_t height, uint32_t supersampling);
    // `display` and `hdr` are the tile's width x height frames (the output's size) at `tile`.
    void add(const eng::frame::ViewTile& tile, const eng::io::ImageF& display, const eng::io::ImageF& hdr);
    // Throws std::logic_error unless every tile of the k x k grid was added exactly once.
    ConvergedTruth finish() const;

  private:
    uint32_t m_width, m_height, m_k;
    std::vector<double> m_display, m_hdr, m_half[2];
    std::vector<uint32_t> m_tilesAdded;
    std::vector<double> m_subPixelLuma; // per sub-pixel (u, v), v k + u: the sum of its hdr luma
};

// The settings that make a request render the truth's frames: the reference at settings.samples
// with sample-rate shading, the request's own effect settings (shadow map size, taps, footprint)
// and view. Exposure: the request's, metered once for the whole view when it asks for auto.
class TruthCache;
ConvergedTruth renderConvergedTruth(FrameRenderer& renderer, const RenderRequest& request,
                                    const TruthSettings& settings, const TruthCache* cache = nullptr);

// On-disk store of truths, one file a key in `dir` (created on first store). A file that does not
// read back whole is ignored and rendered again, never trusted.
class TruthCache {
  public:
    explicit TruthCache(std::filesystem::path dir) : m_dir(std::move(dir)) {}
    const std::filesystem::path& dir() const { return m_dir; }
    std::optional<ConvergedTruth> load(const std::string& key) const;
    void store(const ConvergedTruth& truth) const; // throws eng::io::IoError when it cannot write

  private:
    std::filesystem::path m_dir;
};

// The cache key's hash (hex) for a truth of `request` rendered at `exposure`: the scene's content
// (geometry, materials, textures, lights), the frame constants of the view, the effect settings,
// the truth settings and the program's binary (any rebuild that changes a byte is a new version).
std::string truthKey(const eng::scene::Scene& scene, const RenderRequest& request, float exposure,
                     const TruthSettings& settings);

// The cache folder the tools use: $AGAA_TRUTH_CACHE if set, else `fallback`.
std::filesystem::path truthCacheDir(const std::filesystem::path& fallback);

} // namespace agaa
