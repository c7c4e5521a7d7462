#include "tools/harness/converged_truth.h"

#include "engine/frame/frame_constants.h"
#include "engine/frame/sample_pattern.h"
#include "engine/io/io_error.h"
#include "engine/io/metrics.h"
#include "engine/io/tone_map.h"

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <stdexcept>

namespace agaa {
namespace fs = std::filesystem;

namespace {

constexpr char kCacheMagic[8] = {'A', 'G', 'T', 'R', 'U', 'T', 'H', '2'}; // 2: the mean's error estimate

// FNV-1a, 64 bits: a cache key, not a security boundary.
struct Hash {
    uint64_t h = 1469598103934665603ull;
    void bytes(const void* data, size_t size) {
        const auto* p = static_cast<const unsigned char*>(data);
        for (size_t i = 0; i < size; ++i) {
            h ^= p[i];
            h *= 1099511628211ull;
        }
    }
    template <class T> void value(const T& v) { bytes(&v, sizeof v); }
    template <class T> void vector(const std::vector<T>& v) {
        value(uint64_t(v.size()));
        bytes(v.data(), v.size() * sizeof(T));
    }
    void text(const std::string& s) {
        value(uint64_t(s.size()));
        bytes(s.data(), s.size());
    }
    std::string hex() const {
        char buf[17];
        std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
        return buf;
    }
};

// The program's own binary: the code version, shaders included (they are embedded as SPIR-V).
uint64_t codeVersion() {
    static const uint64_t version = [] {
        Hash h;
        std::ifstream in("/proc/self/exe", std::ios::binary);
        std::vector<char> buf(1 << 20);
        while (in) {
            in.read(buf.data(), std::streamsize(buf.size()));
            h.bytes(buf.data(), size_t(in.gcount()));
        }
        return h.h;
    }();
    return version;
}

} // namespace

void validate(const TruthSettings& s) {
    if (s.supersampling < 1 || s.supersampling > kMaxTruthSupersampling)
        throw std::invalid_argument("truth supersampling " + std::to_string(s.supersampling) +
                                    " is out of range (1.." + std::to_string(kMaxTruthSupersampling) + ")");
    if (s.samples < 1 || s.samples > shared::kMaxSamples || (s.samples > 4 && s.samples % 4 != 0))
        throw std::invalid_argument("truth samples " + std::to_string(s.samples) +
                                    " is out of range (1, 4, 8, ..., " + std::to_string(shared::kMaxSamples) +
                                    ": a multiple of 4 above 4)");
}

double meanLuminance(const eng::io::ImageF& hdr) {
    double sum = 0.0;
    for (size_t p = 0; p + 3 < hdr.rgba.size(); p += 4)
        sum += 0.2126 * hdr.rgba[p] + 0.7152 * hdr.rgba[p + 1] + 0.0722 * hdr.rgba[p + 2];
    return hdr.rgba.empty() ? 0.0 : sum / double(hdr.rgba.size() / 4);
}

double truthErrorEstimate(const eng::io::ImageF& halfA, const eng::io::ImageF& halfB) {
    return 0.5 * eng::io::rmse(eng::io::srgbEncoded(halfA), eng::io::srgbEncoded(halfB));
}

double truthMeanErrorEstimate(const std::vector<double>& subPixelMeans) {
    const size_t m = subPixelMeans.size();
    if (m < 2) return std::numeric_limits<double>::infinity();
    double mean = 0.0;
    for (double v : subPixelMeans)
        mean += v;
    mean /= double(m);
    double squares = 0.0;
    for (double v : subPixelMeans)
        squares += (v - mean) * (v - mean);
    // The sample variance of one draw (m - 1: the mean is estimated from the same draws), and the
    // full truth's mean averages m of them.
    return std::sqrt(squares / double(m - 1) / double(m));
}

TruthAccumulator::TruthAccumulator(uint32_t width, uint32_t height, uint32_t supersampling)
    : m_width(width), m_height(height), m_k(supersampling) {
    validate(TruthSettings{supersampling, 32});
    if (width == 0 || height == 0) throw std::invalid_argument("truth image size must not be 0");
    const size_t n = size_t(width) * height * 4;
    m_display.assign(n, 0.0);
    m_hdr.assign(n, 0.0);
    m_half[0].assign(n, 0.0);
    m_half[1].assign(n, 0.0);
    m_tilesAdded.assign(size_t(m_k) * m_k, 0);
    m_subPixelLuma.assign(size_t(m_k) * m_k, 0.0);
}

void TruthAccumulator::add(const eng::frame::ViewTile& tile, const eng::io::ImageF& display,
                           const eng::io::ImageF& hdr) {
    if (tile.scale != m_k || tile.origin.x % m_width != 0 || tile.origin.y % m_height != 0 ||
        tile.origin.x / m_width >= m_k || tile.origin.y / m_height >= m_k)
        throw std::logic_error("truth tile is not one of the k x k grid of output-sized tiles");
    if (display.width != m_width || display.height != m_height || hdr.width != m_width ||
        hdr.height != m_height || !eng::io::isConsistent(display) || !eng::io::isConsistent(hdr))
        throw std::logic_error("truth tile frame is not of the output's size");
    m_tilesAdded[size_t(tile.origin.y / m_height) * m_k + tile.origin.x / m_width] += 1;
    for (uint32_t y = 0; y < m_height; ++y) {
        const uint32_t Y = tile.origin.y + y; // row of the k-times-larger image
        for (uint32_t x = 0; x < m_width; ++x) {
            const uint32_t X = tile.origin.x + x;
            const size_t out = (size_t(Y / m_k) * m_width + X / m_k) * 4;
            const size_t in = (size_t(y) * m_width + x) * 4;
            std::vector<double>& half = m_half[(X % m_k + Y % m_k) % 2];
            m_subPixelLuma[size_t(Y % m_k) * m_k + X % m_k] +=
                0.2126 * hdr.rgba[in] + 0.7152 * hdr.rgba[in + 1] + 0.0722 * hdr.rgba[in + 2];
            for (int c = 0; c < 4; ++c) {
                m_display[out + c] += display.rgba[in + c];
                m_hdr[out + c] += hdr.rgba[in + c];
                half[out + c] += display.rgba[in + c];
            }
        }
    }
}

ConvergedTruth TruthAccumulator::finish() const {
    for (uint32_t added : m_tilesAdded)
        if (added != 1) throw std::logic_error("truth accumulated without every tile exactly once");
    ConvergedTruth t;
    t.settings.supersampling = m_k;
    const double all = double(m_k) * m_k;
    // Sub-pixels per half: ceil and floor of k^2 / 2 (equal for even k; k = 1 has one half only).
    const double halfCount[2] = {std::ceil(all / 2.0), std::floor(all / 2.0)};
    t.display = eng::io::makeImage(m_width, m_height);
    t.hdr = eng::io::makeImage(m_width, m_height);
    for (int h = 0; h < 2; ++h)
        t.halves[h] = eng::io::makeImage(m_width, m_height);
    for (size_t i = 0; i < m_display.size(); ++i) {
        t.display.rgba[i] = float(m_display[i] / all);
        t.hdr.rgba[i] = float(m_hdr[i] / all);
        for (int h = 0; h < 2; ++h)
            t.halves[h].rgba[i] = halfCount[h] > 0.0 ? float(m_half[h][i] / halfCount[h]) : t.display.rgba[i];
    }
    t.meanLuminance = meanLuminance(t.hdr);
    // k = 1 has no second half: its own error is not measured, reported as unknown (infinite).
    t.errorEstimate =
        m_k == 1 ? std::numeric_limits<double>::infinity() : truthErrorEstimate(t.halves[0], t.halves[1]);
    std::vector<double> subPixelMeans;
    for (double sum : m_subPixelLuma)
        subPixelMeans.push_back(sum / (double(m_width) * m_height));
    t.meanErrorEstimate = truthMeanErrorEstimate(subPixelMeans);
    return t;
}

std::string truthKey(const eng::scene::Scene& scene, const RenderRequest& request, float exposure,
                     const TruthSettings& settings) {
    Hash h;
    h.value(codeVersion());
    h.vector(scene.vertices);
    h.vector(scene.indices);
    for (const eng::scene::Draw& d : scene.draws) {
        h.value(d.firstIndex);
        h.value(d.indexCount);
        h.value(d.material);
    }
    h.vector(eng::frame::makeGpuMaterials(scene));
    for (const eng::scene::Texture& t : scene.textures) {
        h.value(t.width);
        h.value(t.height);
        h.value(t.srgb);
        h.vector(t.rgba8);
    }
    eng::frame::ViewSettings view = request.view;
    view.exposure = exposure;
    view.tile = {};
    const shared::FrameConstants frame =
        eng::frame::makeFrameConstants(scene, view, eng::frame::makeSamplePattern(settings.samples));
    h.value(frame);
    h.vector(eng::frame::makeGpuLights(scene, frame.view));
    // Which lights cast shadows is not in GpuLight, and it changes the truth: two tests rendering
    // one scene with and without its shadows shared a key and, run in parallel, each other's truth.
    for (const eng::scene::Light& l : scene.lights)
        h.value(l.castsShadows);
    const EffectSettings& e = request.settings.effects;
    h.value(e.forceAll);
    h.value(e.shadowMapSize);
    h.value(e.shadowTaps);
    h.value(uint32_t(e.shadowFootprint));
    h.value(request.settings.effects.curvatureRoughness.enabled); // always off: the key's old layout
    h.value(settings.supersampling);
    h.value(settings.samples);
    return h.hex();
}

fs::path truthCacheDir(const fs::path& fallback) {
    const char* env = std::getenv("AGAA_TRUTH_CACHE");
    return env && *env ? fs::path(env) : fallback;
}

ConvergedTruth renderConvergedTruth(FrameRenderer& renderer, const RenderRequest& request,
                                    const TruthSettings& settings, const TruthCache* cache) {
    validate(settings);
    RenderRequest frame = request;
    frame.method = "reference";
    frame.settings.samples = settings.samples;
    frame.settings.sampleRateShading = true; // materials, textures and alpha per sample
    frame.settings.debug.clear();            // the lit frame, whatever view the caller's method shows
    // The material's own roughness: the truth is what specular anti-aliasing approximates.
    frame.settings.effects.curvatureRoughness.enabled = false;
    frame.warmupFrames = 0;
    frame.timedFrames = 1;
    frame.extraPasses = nullptr;
    // Metered on the whole view once (FrameRenderer caches it), the exposure every method gets.
    frame.view.exposure = renderer.exposureFor(request);
    frame.autoExposure = false;
    frame.view.tile = {};

    const std::string key = truthKey(renderer.scene(), frame, frame.view.exposure, settings);
    if (cache)
        if (std::optional<ConvergedTruth> hit = cache->load(key)) return *hit;

    const uint32_t k = settings.supersampling, w = request.view.width, h = request.view.height;
    TruthAccumulator acc(w, h, k);
    for (uint32_t ty = 0; ty < k; ++ty)
        for (uint32_t tx = 0; tx < k; ++tx) {
            frame.view.tile = {k, {tx * w, ty * h}};
            RenderResult r = renderer.render(frame);
            if (!eng::io::allFinite(r.display) || !eng::io::allFinite(r.hdr))
                throw std::runtime_error("the truth's tile (" + std::to_string(tx) + ", " +
                                         std::to_string(ty) + ") contains NaN or Inf");
            acc.add(frame.view.tile, r.display, r.hdr);
        }
    ConvergedTruth truth = acc.finish();
    truth.settings = settings;
    truth.exposure = frame.view.exposure;
    truth.key = key;
    if (cache) cache->store(truth);
    return truth;
}

// File: magic, key (16 hex), k, samples, exposure, error estimate, mean luminance, the mean's error
// estimate, width, height,
// then display, hdr, half A, half B as RGBA floats.
std::optional<ConvergedTruth> TruthCache::load(const std::string& key) const {
    std::ifstream in(m_dir / (key + ".truth"), std::ios::binary);
    if (!in) return std::nullopt;
    char magic[8];
    char stored[16];
    ConvergedTruth t;
    uint32_t w = 0, h = 0;
    in.read(magic, 8);
    in.read(stored, 16);
    in.read(reinterpret_cast<char*>(&t.settings.supersampling), 4);
    in.read(reinterpret_cast<char*>(&t.settings.samples), 4);
    in.read(reinterpret_cast<char*>(&t.exposure), 4);
    in.read(reinterpret_cast<char*>(&t.errorEstimate), 8);
    in.read(reinterpret_cast<char*>(&t.meanLuminance), 8);
    in.read(reinterpret_cast<char*>(&t.meanErrorEstimate), 8);
    in.read(reinterpret_cast<char*>(&w), 4);
    in.read(reinterpret_cast<char*>(&h), 4);
    if (!in || std::memcmp(magic, kCacheMagic, 8) != 0 || std::string(stored, 16) != key || w == 0 ||
        h == 0 || uint64_t(w) * h > eng::io::kMaxImagePixels)
        return std::nullopt;
    for (eng::io::ImageF* img : {&t.display, &t.hdr, &t.halves[0], &t.halves[1]}) {
        *img = eng::io::makeImage(w, h);
        in.read(reinterpret_cast<char*>(img->rgba.data()), std::streamsize(img->rgba.size() * sizeof(float)));
    }
    if (!in || in.peek() != std::char_traits<char>::eof()) return std::nullopt;
    if (!eng::io::allFinite(t.display) || !eng::io::allFinite(t.hdr)) return std::nullopt;
    t.key = key;
    t.fromCache = true;
    return t;
}

void TruthCache::store(const ConvergedTruth& t) const {
    std::error_code ec;
    fs::create_directories(m_dir, ec);
    if (ec) throw eng::io::IoError(m_dir, "cannot create the truth cache folder: " + ec.message());
    // Written to a temporary name and renamed: a run killed mid-write leaves no half file behind.
    const fs::path file = m_dir / (t.key + ".truth");
    const fs::path part = m_dir / (t.key + ".truth.part");
    {
        std::ofstream out(part, std::ios::binary | std::ios::trunc);
        if (!out) throw eng::io::IoError(part, "cannot write the truth cache file");
        out.write(kCacheMagic, 8);
        out.write(t.key.data(), 16);
        out.write(reinterpret_cast<const char*>(&t.settings.supersampling), 4);
        out.write(reinterpret_cast<const char*>(&t.settings.samples), 4);
        out.write(reinterpret_cast<const char*>(&t.exposure), 4);
        out.write(reinterpret_cast<const char*>(&t.errorEstimate), 8);
        out.write(reinterpret_cast<const char*>(&t.meanLuminance), 8);
        out.write(reinterpret_cast<const char*>(&t.meanErrorEstimate), 8);
        out.write(reinterpret_cast<const char*>(&t.display.width), 4);
        out.write(reinterpret_cast<const char*>(&t.display.height), 4);
        for (const eng::io::ImageF* img : {&t.display, &t.hdr, &t.halves[0], &t.halves[1]})
            out.write(reinterpret_cast<const char*>(img->rgba.data()),
                      std::streamsize(img->rgba.size() * sizeof(float)));
        if (!out) throw eng::io::IoError(part, "cannot write the truth cache file");
    }
    fs::rename(part, file, ec);
    if (ec) throw eng::io::IoError(file, "cannot write the truth cache file: " + ec.message());
}

} // namespace agaa
