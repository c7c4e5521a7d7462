#include "engine/scene/gltf_materials.h"

#include "engine/scene/gltf_accessor.h"
#include "engine/scene/scene_error.h"

#include <stb_image.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <utility>

namespace eng::scene {

namespace {

// 16k x 16k: larger than any GPU allows for a 2D texture; refuses absurd headers
// before allocating.
constexpr uint64_t kMaxTexels = 16384ull * 16384ull;

// stb_image's reason for its last failure. It gives none for some (a corrupt zlib stream in a
// PNG returns NULL without setting one), and a NULL appended to a std::string would crash.
std::string decodeFailure() {
    const char* reason = stbi_failure_reason();
    return reason != nullptr ? std::string(reason) : std::string("corrupt or unsupported image data");
}

uint8_t toUnorm8(float v) {
    return static_cast<uint8_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
}

class MaterialConverter {
  public:
    MaterialConverter(const tinygltf::Model& model, const std::string& source, Scene& scene)
        : m_model(model), m_source(source), m_scene(scene) {}

    void run() {
        for (size_t i = 0; i < m_model.materials.size(); ++i) {
            m_scene.materials.push_back(
                convert(m_model.materials[i], "materials[" + std::to_string(i) + "]"));
        }
    }

  private:
    void warn(const std::string& what) { m_scene.stats.warnings.push_back(m_source + ": " + what); }

    float finiteOr(double v, float fallback, const std::string& field) {
        if (!std::isfinite(v)) {
            warn(field + ": not finite, using " + std::to_string(fallback));
            return fallback;
        }
        return static_cast<float>(v);
    }

    float unitOr(double v, float fallback, const std::string& field) {
        const float f = finiteOr(v, fallback, field);
        if (f < 0.0f || f > 1.0f) {
            warn(field + ": " + std::to_string(f) + " outside [0, 1], clamped");
        }
        return std::clamp(f, 0.0f, 1.0f);
    }

    Material convert(const tinygltf::Material& in, const std::string& field) {
        Material out;
        out.name = in.name.empty() ? field : in.name;
        const auto& pbr = in.pbrMetallicRoughness;
        const std::string pbrField = field + ".pbrMetallicRoughness";
        if (pbr.baseColorFactor.size() == 4) {
            for (int c = 0; c < 4; ++c) {
                out.baseColorFactor[c] = unitOr(pbr.baseColorFactor[static_cast<size_t>(c)], 1.0f,
                                                pbrField + ".baseColorFactor[" + std::to_string(c) + "]");
            }
        } else {
            warn(pbrField + ".baseColorFactor: needs 4 numbers, has " +
                 std::to_string(pbr.baseColorFactor.size()) + "; using white");
        }
        out.metallicFactor = unitOr(pbr.metallicFactor, 1.0f, pbrField + ".metallicFactor");
        out.roughnessFactor = unitOr(pbr.roughnessFactor, 1.0f, pbrField + ".roughnessFactor");
        out.baseColorTexture =
            texture(pbr.baseColorTexture.index, true, pbrField + ".baseColorTexture.index");
        out.metallicRoughnessTexture =
            texture(pbr.metallicRoughnessTexture.index, false, pbrField + ".metallicRoughnessTexture.index");
        out.textureTransforms[0] = textureTransform(
            pbr.baseColorTexture.extensions, pbr.baseColorTexture.texCoord, pbrField + ".baseColorTexture");
        out.textureTransforms[1] =
            textureTransform(pbr.metallicRoughnessTexture.extensions, pbr.metallicRoughnessTexture.texCoord,
                             pbrField + ".metallicRoughnessTexture");
        out.textureTransforms[2] = textureTransform(in.normalTexture.extensions, in.normalTexture.texCoord,
                                                    field + ".normalTexture");
        out.textureTransforms[3] = textureTransform(in.emissiveTexture.extensions,
                                                    in.emissiveTexture.texCoord, field + ".emissiveTexture");

        out.normalTexture = texture(in.normalTexture.index, false, field + ".normalTexture.index");
        out.normalScale = finiteOr(in.normalTexture.scale, 1.0f, field + ".normalTexture.scale");

        if (in.emissiveFactor.size() == 3) {
            for (int c = 0; c < 3; ++c) {
                out.emissiveFactor[c] = unitOr(in.emissiveFactor[static_cast<size_t>(c)], 0.0f,
                                               field + ".emissiveFactor[" + std::to_string(c) + "]");
            }
        } else if (!in.emissiveFactor.empty()) {
            warn(field + ".emissiveFactor: needs 3 numbers, has " + std::to_string(in.emissiveFactor.size()) +
                 "; using black");
        }
        out.emissiveTexture = texture(in.emissiveTexture.index, true, field + ".emissiveTexture.index");
        out.emissiveStrength = emissiveStrength(in, field);

        if (in.alphaMode == "OPAQUE" || in.alphaMode.empty()) {
            out.alphaMode = AlphaMode::Opaque;
        } else if (in.alphaMode == "MASK") {
            out.alphaMode = AlphaMode::Mask;
        } else if (in.alphaMode == "BLEND") {
            out.alphaMode = AlphaMode::Blend;
        } else {
            warn(field + ".alphaMode: '" + in.alphaMode + "' is not OPAQUE, MASK or BLEND; using OPAQUE");
        }
        out.alphaCutoff = finiteOr(in.alphaCutoff, 0.5f, field + ".alphaCutoff");
        if (out.alphaCutoff < 0.0f) {
            warn(field + ".alphaCutoff: negative, using 0");
            out.alphaCutoff = 0.0f;
        }
        out.doubleSided = in.doubleSided;
        return out;
    }

    // KHR_texture_transform on a textureInfo, and the UV set it reads (the info's texCoord or the
    // extension's override): TEXCOORD_0 or TEXCOORD_1.
    TextureTransform textureTransform(const tinygltf::ExtensionMap& extensions, int texCoord,
                                      const std::string& field) {
        TextureTransform t;
        int set = texCoord;
        const auto it = extensions.find("KHR_texture_transform");
        if (it != extensions.end() && it->second.IsObject()) {
            const tinygltf::Value& e = it->second;
            const std::string f = field + ".extensions.KHR_texture_transform";
            auto pair = [&](const char* name, glm::vec2& out) {
                if (!e.Has(name)) return;
                const tinygltf::Value& v = e.Get(name);
                if (!v.IsArray() || v.ArrayLen() != 2 || !v.Get(0).IsNumber() || !v.Get(1).IsNumber()) {
                    warn(f + "." + name + ": needs 2 numbers; ignored");
                    return;
                }
                out = {finiteOr(v.Get(0).GetNumberAsDouble(), out.x, f + "." + name + "[0]"),
                       finiteOr(v.Get(1).GetNumberAsDouble(), out.y, f + "." + name + "[1]")};
            };
            pair("offset", t.offset);
            pair("scale", t.scale);
            if (e.Has("rotation")) {
                const tinygltf::Value& v = e.Get("rotation");
                if (v.IsNumber())
                    t.rotation = finiteOr(v.GetNumberAsDouble(), 0.0f, f + ".rotation");
                else
                    warn(f + ".rotation: not a number; ignored");
            }
            if (e.Has("texCoord") && e.Get("texCoord").IsInt()) set = e.Get("texCoord").GetNumberAsInt();
        }
        if (set == 1) t.texCoord = 1;
        if (set > 1 || set < 0)
            warn(field + ": uses TEXCOORD_" + std::to_string(set) +
                 "; the renderer carries TEXCOORD_0 and TEXCOORD_1, TEXCOORD_0 is used instead");
        return t;
    }

    float emissiveStrength(const tinygltf::Material& in, const std::string& field) {
        const auto it = in.extensions.find("KHR_materials_emissive_strength");
        if (it == in.extensions.end() || !it->second.IsObject() || !it->second.Has("emissiveStrength")) {
            return 1.0f;
        }
        const std::string f = field + ".extensions.KHR_materials_emissive_strength.emissiveStrength";
        const tinygltf::Value& v = it->second.Get("emissiveStrength");
        if (!v.IsNumber()) {
            warn(f + ": not a number, using 1");
            return 1.0f;
        }
        const float s = finiteOr(v.GetNumberAsDouble(), 1.0f, f);
        if (s < 0.0f) {
            warn(f + ": negative, using 0");
            return 0.0f;
        }
        return s;
    }

    int32_t texture(int index, bool srgb, const std::string& field) {
        if (index < 0) {
            return -1;
        }
        if (static_cast<size_t>(index) >= m_model.textures.size()) {
            throw SceneError(m_source + ": " + field + ": texture " + std::to_string(index) +
                             " out of range (" + std::to_string(m_model.textures.size()) + " textures)");
        }
        const auto key = std::make_pair(index, srgb);
        if (const auto it = m_converted.find(key); it != m_converted.end()) {
            return it->second;
        }
        const tinygltf::Texture& tex = m_model.textures[static_cast<size_t>(index)];
        const std::string texField = "textures[" + std::to_string(index) + "].source";
        if (tex.source < 0) {
            // Only image extensions (KTX2, WebP) leave source unset; we decode none of them.
            warn(texField + ": no core image source; texture ignored");
            return -1;
        }
        if (static_cast<size_t>(tex.source) >= m_model.images.size()) {
            throw SceneError(m_source + ": " + texField + ": image " + std::to_string(tex.source) +
                             " out of range (" + std::to_string(m_model.images.size()) + " images)");
        }
        const std::string imageField = "images[" + std::to_string(tex.source) + "]";
        const tinygltf::Image& image = m_model.images[static_cast<size_t>(tex.source)];

        Texture out;
        out.name = !tex.name.empty() ? tex.name : (!image.name.empty() ? image.name : imageField);
        out.srgb = srgb;
        decode(image, imageField, out);
        m_scene.textures.push_back(std::move(out));
        const auto sceneIndex = static_cast<int32_t>(m_scene.textures.size() - 1);
        m_converted[key] = sceneIndex;
        return sceneIndex;
    }

    void decode(const tinygltf::Image& image, const std::string& field, Texture& out) {
        if (!image.image.empty()) {
            out.rgba8 = toRgba8(image, m_source, field);
            out.width = static_cast<uint32_t>(image.width);
            out.height = static_cast<uint32_t>(image.height);
            return;
        }
        // An in-memory model (procedural scenes) may carry the encoded file in a
        // bufferView instead of decoded pixels.
        if (image.bufferView < 0) {
            throw SceneError(m_source + ": " + field + ": no decoded pixels and no bufferView");
        }
        const std::vector<uint8_t> bytes =
            bufferViewBytes(m_model, m_source, image.bufferView, field + ".bufferView");
        int w = 0, h = 0, comp = 0;
        stbi_uc* pixels =
            stbi_load_from_memory(bytes.data(), static_cast<int>(bytes.size()), &w, &h, &comp, 4);
        if (pixels == nullptr) {
            throw SceneError(m_source + ": " + field + ".bufferView: cannot decode image (" +
                             decodeFailure() + ")");
        }
        out.width = static_cast<uint32_t>(w);
        out.height = static_cast<uint32_t>(h);
        out.rgba8.assign(pixels, pixels + static_cast<size_t>(w) * static_cast<size_t>(h) * 4);
        stbi_image_free(pixels);
    }

    const tinygltf::Model& m_model;
    const std::string& m_source;
    Scene& m_scene;
    std::map<std::pair<int, bool>, int32_t> m_converted; // (glTF texture, srgb) -> Scene::textures index
};

} // namespace

std::vector<uint8_t> toRgba8(const tinygltf::Image& image, const std::string& source,
                             const std::string& field) {
    const int comps = image.component;
    const int bits = image.bits;
    if (image.width <= 0 || image.height <= 0 ||
        static_cast<uint64_t>(image.width) * static_cast<uint64_t>(image.height) > kMaxTexels) {
        throw SceneError(source + ": " + field + ": size " + std::to_string(image.width) + "x" +
                         std::to_string(image.height) + " is outside 1..16384 squared texels");
    }
    if (comps < 1 || comps > 4 || (bits != 8 && bits != 16 && bits != 32)) {
        throw SceneError(source + ": " + field + ": " + std::to_string(comps) + " channels of " +
                         std::to_string(bits) +
                         " bits; supported are 1-4 channels of 8, 16 or 32 (float) bits");
    }
    const size_t texels = static_cast<size_t>(image.width) * static_cast<size_t>(image.height);
    const size_t bytesPerChannel = static_cast<size_t>(bits / 8);
    const size_t needed = texels * static_cast<size_t>(comps) * bytesPerChannel;
    if (image.image.size() < needed) {
        throw SceneError(source + ": " + field + ": " + std::to_string(image.image.size()) +
                         " bytes of pixels, " + std::to_string(needed) + " needed");
    }
    auto channel = [&](size_t texel, int c) -> uint8_t {
        const uint8_t* p = image.image.data() +
                           (texel * static_cast<size_t>(comps) + static_cast<size_t>(c)) * bytesPerChannel;
        if (bits == 8) {
            return p[0];
        }
        if (bits == 16) {
            uint16_t v;
            std::memcpy(&v, p, 2);
            return static_cast<uint8_t>((static_cast<uint32_t>(v) * 255u + 32767u) / 65535u);
        }
        float f;
        std::memcpy(&f, p, 4);
        return toUnorm8(std::isfinite(f) ? f : 0.0f);
    };
    std::vector<uint8_t> rgba(texels * 4);
    for (size_t t = 0; t < texels; ++t) {
        uint8_t* o = rgba.data() + t * 4;
        switch (comps) {
        case 1:
            o[0] = o[1] = o[2] = channel(t, 0);
            o[3] = 255;
            break;
        case 2:
            o[0] = o[1] = o[2] = channel(t, 0);
            o[3] = channel(t, 1);
            break;
        case 3:
            o[0] = channel(t, 0);
            o[1] = channel(t, 1);
            o[2] = channel(t, 2);
            o[3] = 255;
            break;
        default:
            for (int c = 0; c < 4; ++c)
                o[c] = channel(t, c);
            break;
        }
    }
    return rgba;
}

bool decodeImageRgba8(tinygltf::Image* image, const int imageIndex, std::string* err, std::string* /*warn*/,
                      int /*reqWidth*/, int /*reqHeight*/, const unsigned char* bytes, int size,
                      void* /*userData*/) {
    if (image->bufferView >= 0) {
        // tinygltf hands over bufferView bytes without checking the view lies
        // inside its buffer; leave them undecoded and let the converter decode
        // them after bufferViewBytes() has validated the range.
        return true;
    }
    int w = 0, h = 0, comp = 0;
    stbi_uc* pixels = stbi_load_from_memory(bytes, size, &w, &h, &comp, 4);
    if (pixels == nullptr) {
        if (err != nullptr) {
            // Which image: its index and where it came from (tinygltf clears a data URI before
            // decoding it; one that is still there is named, never echoed).
            const std::string from = image->uri.empty() || image->uri.rfind("data:", 0) == 0
                                         ? std::string("embedded")
                                         : "'" + image->uri + "'";
            *err += "images[" + std::to_string(imageIndex) + "] (" + from + "): cannot decode (" +
                    decodeFailure() + ")\n";
        }
        return false;
    }
    image->width = w;
    image->height = h;
    image->component = 4;
    image->bits = 8;
    image->pixel_type = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
    image->image.assign(pixels, pixels + static_cast<size_t>(w) * static_cast<size_t>(h) * 4);
    stbi_image_free(pixels);
    return true;
}

void convertMaterials(const tinygltf::Model& model, const std::string& source, Scene& scene) {
    MaterialConverter(model, source, scene).run();
}

} // namespace eng::scene
