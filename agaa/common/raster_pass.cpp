#include "agaa/common/raster_pass.h"

#include <algorithm>
#include <cstring>

namespace agaa {

const char* rasterOutputName(RasterOutput output) {
    switch (output) {
    case RasterOutput::SampleGBuffer:
        return "sample G-buffer";
    case RasterOutput::SampleGBufferPrimitive:
        return "sample G-buffer with primitive ids";
    case RasterOutput::SurfaceVisibility:
        return "surface visibility";
    case RasterOutput::SurfaceFill:
        return "surface fill";
    case RasterOutput::ShadowDepth:
        return "shadow depth";
    case RasterOutput::AggregateVisibility:
        return "aggregate visibility";
    case RasterOutput::AggregateAccumulation:
        return "aggregate accumulation";
    }
    return "unknown";
}

eng::vk::GraphicsPipelineDesc rasterPipelineState(const RasterPass& pass, bool twoSided) {
    eng::vk::GraphicsPipelineDesc d;
    d.colorFormats = pass.colorFormats;
    d.depthFormat = pass.depthFormat;
    d.samples = pass.samples;
    d.sampleShading = pass.sampleRateShading;
    d.cullMode = pass.bothFaces || twoSided ? VK_CULL_MODE_NONE : VK_CULL_MODE_BACK_BIT;
    d.depthCompare = pass.depthCompare;
    d.depthWrite = pass.depthWrite;
    d.stencilTest = pass.stencilTest;
    d.stencil = pass.stencil;
    return d;
}

bool RasterPass::defined(std::string_view macro) const {
    return std::find(defines.begin(), defines.end(), macro) != defines.end();
}

bool RasterPass::operator==(const RasterPass& o) const {
    return name == o.name && output == o.output && colorFormats == o.colorFormats &&
           depthFormat == o.depthFormat && depthCompare == o.depthCompare && depthWrite == o.depthWrite &&
           samples == o.samples && layers == o.layers && sampleRateShading == o.sampleRateShading &&
           bothFaces == o.bothFaces && stencilTest == o.stencilTest &&
           std::memcmp(&stencil, &o.stencil, sizeof stencil) == 0 && moduleSet == o.moduleSet &&
           specialization == o.specialization && defines == o.defines;
}

} // namespace agaa
