#include "agaa/fxaa/fxaa_reference.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace agaa {
namespace {

struct Preset {
    uint32_t id;
    std::array<float, 12> steps;
    uint32_t count;
};

// FXAA 3.11 FXAA_QUALITY__PS and __P0..P11 per preset.
constexpr Preset kPresets[] = {
    {10, {1.5f, 3.0f, 12.0f}, 3},
    {11, {1.0f, 1.5f, 3.0f, 12.0f}, 4},
    {12, {1.0f, 1.5f, 2.0f, 4.0f, 12.0f}, 5},
    {13, {1.0f, 1.5f, 2.0f, 2.0f, 4.0f, 12.0f}, 6},
    {14, {1.0f, 1.5f, 2.0f, 2.0f, 2.0f, 4.0f, 12.0f}, 7},
    {15, {1.0f, 1.5f, 2.0f, 2.0f, 2.0f, 2.0f, 4.0f, 12.0f}, 8},
    {20, {1.5f, 2.0f, 8.0f}, 3},
    {21, {1.0f, 1.5f, 2.0f, 8.0f}, 4},
    {22, {1.0f, 1.5f, 2.0f, 2.0f, 8.0f}, 5},
    {23, {1.0f, 1.5f, 2.0f, 2.0f, 2.0f, 8.0f}, 6},
    {24, {1.0f, 1.5f, 2.0f, 2.0f, 2.0f, 3.0f, 8.0f}, 7},
    {25, {1.0f, 1.5f, 2.0f, 2.0f, 2.0f, 2.0f, 4.0f, 8.0f}, 8},
    {26, {1.0f, 1.5f, 2.0f, 2.0f, 2.0f, 2.0f, 2.0f, 4.0f, 8.0f}, 9},
    {27, {1.0f, 1.5f, 2.0f, 2.0f, 2.0f, 2.0f, 2.0f, 2.0f, 4.0f, 8.0f}, 10},
    {28, {1.0f, 1.5f, 2.0f, 2.0f, 2.0f, 2.0f, 2.0f, 2.0f, 2.0f, 4.0f, 8.0f}, 11},
    {29, {1.0f, 1.5f, 2.0f, 2.0f, 2.0f, 2.0f, 2.0f, 2.0f, 2.0f, 2.0f, 4.0f, 8.0f}, 12},
    {39, {1.0f, 1.0f, 1.0f, 1.0f, 1.0f, 1.5f, 2.0f, 2.0f, 2.0f, 2.0f, 4.0f, 8.0f}, 12},
};

struct Reader {
    const eng::io::ImageF& image;
    int w, h;
    const float* texel(int x, int y) const {
        x = std::clamp(x, 0, w - 1); // the pass clamps to the edge
        y = std::clamp(y, 0, h - 1);
        return &image.rgba[(size_t(y) * size_t(w) + size_t(x)) * 4];
    }
    float luma(int x, int y) const {
        const float* c = texel(x, y);
        return std::sqrt(std::max(c[0] * 0.299f + c[1] * 0.587f + c[2] * 0.114f, 0.0f));
    }
    static float lerp(float a, float b, float t) { return a + (b - a) * t; }
    float lumaBilinear(float px, float py) const {
        float fx = px - 0.5f, fy = py - 0.5f;
        float ix = std::floor(fx), iy = std::floor(fy);
        float wx = fx - ix, wy = fy - iy;
        int x = int(ix), y = int(iy);
        float top = lerp(luma(x, y), luma(x + 1, y), wx);
        float bottom = lerp(luma(x, y + 1), luma(x + 1, y + 1), wx);
        return lerp(top, bottom, wy);
    }
};

} // namespace

std::span<const float> fxaaPresetSteps(uint32_t preset) {
    for (const Preset& p : kPresets)
        if (p.id == preset) return {p.steps.data(), p.count};
    throw std::invalid_argument("fxaa: quality preset " + std::to_string(preset) +
                                " is unknown (allowed: " + fxaaPresetNames() + ")");
}

std::string fxaaPresetNames() {
    std::string s;
    for (const Preset& p : kPresets)
        s += (s.empty() ? "" : ", ") + std::to_string(p.id);
    return s;
}

void checkFxaaSettings(const FxaaSettings& s) {
    fxaaPresetSteps(s.preset);
    if (!(s.subpix >= 0.0f && s.subpix <= 1.0f))
        throw std::invalid_argument("fxaa: subpix " + std::to_string(s.subpix) + " is out of range [0, 1]");
    if (!(s.edgeThreshold >= 0.0f && s.edgeThreshold <= 1.0f))
        throw std::invalid_argument("fxaa: edgeThreshold " + std::to_string(s.edgeThreshold) +
                                    " is out of range [0, 1]");
    // > 0 keeps 1/range finite in the sub-pixel step (range >= edgeThresholdMin there).
    if (!(s.edgeThresholdMin > 0.0f && s.edgeThresholdMin <= 1.0f))
        throw std::invalid_argument("fxaa: edgeThresholdMin " + std::to_string(s.edgeThresholdMin) +
                                    " is out of range (0, 1]");
}

float fxaaLuma(const eng::io::ImageF& image, int x, int y) {
    return Reader{image, int(image.width), int(image.height)}.luma(x, y);
}

bool fxaaIsEdgePixel(const eng::io::ImageF& image, int x, int y, const FxaaSettings& s) {
    Reader r{image, int(image.width), int(image.height)};
    float lumaM = r.luma(x, y), lumaN = r.luma(x, y - 1), lumaS = r.luma(x, y + 1);
    float lumaW = r.luma(x - 1, y), lumaE = r.luma(x + 1, y);
    float rangeMax = std::max(std::max(lumaN, lumaW), std::max(lumaE, std::max(lumaS, lumaM)));
    float rangeMin = std::min(std::min(lumaN, lumaW), std::min(lumaE, std::min(lumaS, lumaM)));
    return !(rangeMax - rangeMin < std::max(s.edgeThresholdMin, rangeMax * s.edgeThreshold));
}

// Step numbers as in shaders/glsl/fxaa/fxaa.comp.
eng::io::ImageF fxaaReference(const eng::io::ImageF& display, const FxaaSettings& s,
                              std::vector<float>* decisionMargins) {
    checkFxaaSettings(s);
    const std::span<const float> steps = fxaaPresetSteps(s.preset);
    const uint32_t stepCount = uint32_t(steps.size());
    const int w = int(display.width), h = int(display.height);
    Reader r{display, w, h};
    eng::io::ImageF out = display;
    if (decisionMargins) decisionMargins->assign(size_t(w) * size_t(h), INFINITY);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            float* o = &out.rgba[(size_t(y) * size_t(w) + size_t(x)) * 4];
            o[3] = 1.0f;
            float unused = INFINITY;
            float& margin = decisionMargins ? (*decisionMargins)[size_t(y) * size_t(w) + size_t(x)] : unused;
            auto decide = [&margin](float a, float b) { margin = std::min(margin, std::abs(a - b)); };
            // 1. local contrast
            float lumaM = r.luma(x, y), lumaN = r.luma(x, y - 1), lumaS = r.luma(x, y + 1);
            float lumaW = r.luma(x - 1, y), lumaE = r.luma(x + 1, y);
            float rangeMax = std::max(std::max(lumaN, lumaW), std::max(lumaE, std::max(lumaS, lumaM)));
            float rangeMin = std::min(std::min(lumaN, lumaW), std::min(lumaE, std::min(lumaS, lumaM)));
            float range = rangeMax - rangeMin;
            decide(range, std::max(s.edgeThresholdMin, rangeMax * s.edgeThreshold));
            if (range < std::max(s.edgeThresholdMin, rangeMax * s.edgeThreshold)) continue;
            float lumaNW = r.luma(x - 1, y - 1), lumaNE = r.luma(x + 1, y - 1);
            float lumaSW = r.luma(x - 1, y + 1), lumaSE = r.luma(x + 1, y + 1);
            // 2. sub-pixel aliasing
            float lowpass =
                (2.0f * (lumaN + lumaS + lumaW + lumaE) + (lumaNW + lumaNE + lumaSW + lumaSE)) / 12.0f;
            float subpixC = std::clamp(std::abs(lowpass - lumaM) / range, 0.0f, 1.0f);
            float subpixF = (-2.0f * subpixC + 3.0f) * subpixC * subpixC;
            float subpixBlend = subpixF * subpixF * s.subpix;
            // 3. orientation
            float edgeHorz = std::abs(-2.0f * lumaW + lumaNW + lumaSW) +
                             2.0f * std::abs(-2.0f * lumaM + lumaN + lumaS) +
                             std::abs(-2.0f * lumaE + lumaNE + lumaSE);
            float edgeVert = std::abs(-2.0f * lumaN + lumaNW + lumaNE) +
                             2.0f * std::abs(-2.0f * lumaM + lumaW + lumaE) +
                             std::abs(-2.0f * lumaS + lumaSW + lumaSE);
            bool horzSpan = edgeHorz >= edgeVert;
            decide(edgeHorz, edgeVert);
            int acrossX = horzSpan ? 0 : 1, acrossY = horzSpan ? 1 : 0;
            float alongX = horzSpan ? 1.0f : 0.0f, alongY = horzSpan ? 0.0f : 1.0f;
            // 4. side
            float luma1 = horzSpan ? lumaN : lumaW, luma2 = horzSpan ? lumaS : lumaE;
            float gradient1 = luma1 - lumaM, gradient2 = luma2 - lumaM;
            bool negativeSide = std::abs(gradient1) >= std::abs(gradient2);
            decide(std::abs(gradient1), std::abs(gradient2));
            float gradientScaled = 0.25f * std::max(std::abs(gradient1), std::abs(gradient2));
            float lengthSign = negativeSide ? -1.0f : 1.0f;
            float lumaLocalAverage = 0.5f * ((negativeSide ? luma1 : luma2) + lumaM);
            // 5. end-of-edge search
            float bx = float(x) + 0.5f + 0.5f * lengthSign * float(acrossX);
            float by = float(y) + 0.5f + 0.5f * lengthSign * float(acrossY);
            float nx = bx - alongX * steps[0], ny = by - alongY * steps[0];
            float px = bx + alongX * steps[0], py = by + alongY * steps[0];
            float lumaEndN = r.lumaBilinear(nx, ny) - lumaLocalAverage;
            float lumaEndP = r.lumaBilinear(px, py) - lumaLocalAverage;
            bool doneN = std::abs(lumaEndN) >= gradientScaled;
            bool doneP = std::abs(lumaEndP) >= gradientScaled;
            decide(std::abs(lumaEndN), gradientScaled);
            decide(std::abs(lumaEndP), gradientScaled);
            for (uint32_t i = 1; i < stepCount; ++i) {
                if (!doneN) nx -= alongX * steps[i], ny -= alongY * steps[i];
                if (!doneP) px += alongX * steps[i], py += alongY * steps[i];
                if ((doneN && doneP) || i + 1 == stepCount) break;
                if (!doneN) lumaEndN = r.lumaBilinear(nx, ny) - lumaLocalAverage;
                if (!doneP) lumaEndP = r.lumaBilinear(px, py) - lumaLocalAverage;
                if (!doneN) decide(std::abs(lumaEndN), gradientScaled);
                if (!doneP) decide(std::abs(lumaEndP), gradientScaled);
                doneN = std::abs(lumaEndN) >= gradientScaled;
                doneP = std::abs(lumaEndP) >= gradientScaled;
            }
            // 6. blend across the edge
            float cx = float(x) + 0.5f, cy = float(y) + 0.5f;
            float dstN = horzSpan ? cx - nx : cy - ny;
            float dstP = horzSpan ? px - cx : py - cy;
            bool centreBelow = lumaM - lumaLocalAverage < 0.0f;
            bool nearerN = dstN < dstP;
            bool goodSpan = ((nearerN ? lumaEndN : lumaEndP) < 0.0f) != centreBelow;
            decide(lumaM, lumaLocalAverage);
            decide(nearerN ? lumaEndN : lumaEndP, 0.0f);
            float pixelOffset = -std::min(dstN, dstP) / (dstN + dstP) + 0.5f;
            float offset = std::max(goodSpan ? pixelOffset : 0.0f, subpixBlend);
            int sx = negativeSide ? -acrossX : acrossX, sy = negativeSide ? -acrossY : acrossY;
            const float* m = r.texel(x, y);
            const float* nb = r.texel(x + sx, y + sy);
            for (int c = 0; c < 3; ++c)
                o[c] = m[c] + (nb[c] - m[c]) * offset;
        }
    return out;
}

} // namespace agaa
