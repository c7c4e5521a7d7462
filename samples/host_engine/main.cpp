// host_engine: a host engine that embeds the module with its own content (issue 50). It imports a
// glTF file with tinygltf into its own vertex layout, material and light list (host_content.h),
// describes the content to the module (agaa::SceneTraits), and records one frame of a method into
// its own command buffer (agaa::FrameRecorder) with its own drawer, its own shaders (shaders/,
// compiled against the installed GLSL) and the stand-in environment. It includes installed
// headers only and uses none of the module's scene types (eng::scene::Scene, GpuScene).
//
//   host_engine FILE.gltf METHOD SIZE OUT.exr SHADER_DIR [--compare REF.exr]
//
// OUT.exr: the frame's HDR. --compare: display RMSE (ACES tone map, the project's display transform,
// as tools/imgdiff) against REF.exr, e.g. agaa-render's frame of the same file; exit 1 above
// 1e-4. What it imports: triangle primitives with POSITION, NORMAL and indices, constant
// metallic-roughness materials, punctual lights (extras.castsShadows, or the first directional
// light), the first perspective camera; anything else is refused by name.
// Exit codes: 0 rendered (and within 1e-4), 1 a validation message or a frame over 1e-4, 2 bad
// arguments, a file or shader folder it cannot use, or a pass it has no program for.

#include <agaa/agaa.h>
#include <engine/io/exr.h>
#include <engine/io/metrics.h>
#include <engine/io/tone_map.h>

#include "host_content.h"

#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <tiny_gltf.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

namespace vk = eng::vk;
using host_engine::HostDraw;
using host_engine::HostMesh;
using host_engine::HostVertex;

// What this engine keeps of a file: its own mesh, light list and camera.
struct HostScene {
    HostMesh mesh;
    std::vector<agaa::Light> lights;
    std::optional<agaa::Camera> camera;
};

struct Importer {
    const tinygltf::Model& model;
    const std::string& path;
    HostScene scene;
    bool castsSaid = false;

    // The element `index` of one of the file's arrays, or a refusal naming the field.
    template <typename T>
    const T& element(const std::vector<T>& array, int index, const std::string& field,
                     const char* what) const {
        if (index < 0 || size_t(index) >= array.size())
            refuse(field, std::string(what) + " " + std::to_string(index) + " does not exist (the file has " +
                              std::to_string(array.size()) + ")");
        return array[size_t(index)];
    }

    [[noreturn]] void refuse(const std::string& field, const std::string& what) const {
        throw std::runtime_error(path + ": " + field + ": " + what);
    }

    // glTF's node transform: T R S, the rotation normalised, in double.
    static glm::mat4 local(const tinygltf::Node& node) {
        if (node.matrix.size() == 16) return glm::mat4(glm::make_mat4(node.matrix.data()));
        glm::dquat r(1.0, 0.0, 0.0, 0.0);
        if (node.rotation.size() == 4)
            r = glm::normalize(
                glm::dquat(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]));
        glm::dmat4 m = glm::mat4_cast(r);
        for (int a = 0; a < 3 && node.scale.size() == 3; ++a)
            m[a] *= node.scale[size_t(a)];
        if (node.translation.size() == 3) m[3] = glm::dvec4(glm::make_vec3(node.translation.data()), 1.0);
        return glm::mat4(m);
    }

    template <typename T>
    std::vector<T> read(int accessorIndex, int components, const std::string& field) const {
        if (accessorIndex < 0 || size_t(accessorIndex) >= model.accessors.size())
            refuse(field, "no accessor");
        const tinygltf::Accessor& a = model.accessors[size_t(accessorIndex)];
        const tinygltf::BufferView& view = element(model.bufferViews, a.bufferView, field, "bufferView");
        const tinygltf::Buffer& buffer = element(model.buffers, view.buffer, field, "buffer");
        const size_t stride =
            a.ByteStride(view) > 0 ? size_t(a.ByteStride(view)) : sizeof(T) * size_t(components);
        const size_t start = view.byteOffset + a.byteOffset;
        if (start + (a.count ? (a.count - 1) * stride : 0) + sizeof(T) * size_t(components) >
            buffer.data.size())
            refuse(field, "reads past its buffer");
        std::vector<T> out(a.count * size_t(components));
        for (size_t i = 0; i < a.count; ++i)
            std::memcpy(&out[i * size_t(components)], &buffer.data[start + i * stride],
                        sizeof(T) * size_t(components));
        return out;
    }

    std::vector<uint32_t> indices(int accessorIndex, const std::string& field) const {
        const int type = element(model.accessors, accessorIndex, field, "accessor").componentType;
        std::vector<uint32_t> out;
        if (type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT) return read<uint32_t>(accessorIndex, 1, field);
        if (type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT)
            for (uint16_t i : read<uint16_t>(accessorIndex, 1, field))
                out.push_back(i);
        else if (type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE)
            for (uint8_t i : read<uint8_t>(accessorIndex, 1, field))
                out.push_back(i);
        else
            refuse(field, "component type " + std::to_string(type) + " is not an unsigned integer");
        return out;
    }

    void addMesh(const tinygltf::Mesh& mesh, const glm::mat4& world, const std::string& field) {
        const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(world)));
        for (size_t p = 0; p < mesh.primitives.size(); ++p) {
            const tinygltf::Primitive& prim = mesh.primitives[p];
            const std::string at = field + ".primitives[" + std::to_string(p) + "]";
            if (prim.mode >= 0 && prim.mode != TINYGLTF_MODE_TRIANGLES) refuse(at, "not triangles");
            const auto attribute = [&](const char* name) {
                const auto it = prim.attributes.find(name);
                if (it == prim.attributes.end()) refuse(at + ".attributes", std::string("no ") + name);
                const tinygltf::Accessor& a = element(model.accessors, it->second, at, "accessor");
                if (a.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT || a.type != TINYGLTF_TYPE_VEC3)
                    refuse(at + ".attributes." + name, "this engine reads float VEC3 only");
                return it->second;
            };
            const std::vector<float> positions = read<float>(attribute("POSITION"), 3, at + ".POSITION");
            const std::vector<float> normals = read<float>(attribute("NORMAL"), 3, at + ".NORMAL");
            if (prim.indices < 0) refuse(at, "no indices");
            const std::vector<uint32_t> index = indices(prim.indices, at + ".indices");
            if (normals.size() != positions.size())
                refuse(at + ".attributes.NORMAL", "count differs from POSITION's");
            if (index.size() % 3 != 0) refuse(at + ".indices", "not whole triangles");
            for (uint32_t i : index)
                if (i >= positions.size() / 3)
                    refuse(at + ".indices", "index " + std::to_string(i) + " past the vertices");
            if (prim.material < 0 || size_t(prim.material) >= model.materials.size())
                refuse(at, "no material");
            const tinygltf::Material& m = model.materials[size_t(prim.material)];
            if (m.pbrMetallicRoughness.baseColorTexture.index >= 0 || m.normalTexture.index >= 0 ||
                m.alphaMode != "OPAQUE")
                refuse("materials[" + std::to_string(prim.material) + "]",
                       "this engine's material is constant and opaque (no textures, no alpha)");

            const uint32_t base = uint32_t(scene.mesh.vertices.size());
            for (size_t v = 0; v < positions.size() / 3; ++v) {
                const glm::vec3 p = glm::vec3(world * glm::vec4(glm::make_vec3(&positions[3 * v]), 1.0f));
                const glm::vec3 n = glm::normalize(normalMatrix * glm::make_vec3(&normals[3 * v]));
                scene.mesh.vertices.push_back({{p.x, p.y, p.z}, {n.x, n.y, n.z}});
            }
            if (scene.mesh.vertices.size() - base > 0x10000)
                refuse(at, "more vertices than 16-bit indices reach");
            const auto& f = m.pbrMetallicRoughness;
            HostDraw draw{uint32_t(scene.mesh.indices.size()),
                          uint32_t(index.size()),
                          int32_t(base),
                          {},
                          m.doubleSided};
            draw.material = {{float(f.baseColorFactor[0]), float(f.baseColorFactor[1]),
                              float(f.baseColorFactor[2]), float(f.roughnessFactor)},
                             {float(f.metallicFactor), 0.0f, 0.0f, 0.0f}};
            for (uint32_t i : index)
                scene.mesh.indices.push_back(uint16_t(i));
            scene.mesh.draws.push_back(draw);
        }
    }

    void addLight(int index, const glm::mat4& world, const std::string& field) {
        if (index < 0 || size_t(index) >= model.lights.size()) refuse(field, "no such light");
        const tinygltf::Light& in = model.lights[size_t(index)];
        agaa::Light light;
        light.name = in.name;
        light.type = in.type == "directional" ? agaa::LightType::Directional
                     : in.type == "spot"      ? agaa::LightType::Spot
                                              : agaa::LightType::Point;
        if (in.color.size() == 3)
            light.color = glm::vec3(float(in.color[0]), float(in.color[1]), float(in.color[2]));
        light.intensity = float(in.intensity);
        light.range = light.type == agaa::LightType::Directional ? 0.0f : float(in.range);
        light.innerConeAngle = float(in.spot.innerConeAngle);
        light.outerConeAngle = float(in.spot.outerConeAngle);
        light.position = glm::vec3(world[3]);
        light.direction = glm::normalize(glm::mat3(world) * glm::vec3(0.0f, 0.0f, -1.0f)); // down its -Z
        if (in.extras.IsObject() && in.extras.Has("castsShadows")) {
            const tinygltf::Value& casts = in.extras.Get("castsShadows");
            if (!casts.IsBool()) refuse(field + " light extras.castsShadows", "not a boolean");
            light.castsShadows = casts.Get<bool>();
            castsSaid = true;
        }
        scene.lights.push_back(light);
    }

    void addCamera(int index, const glm::mat4& world, const std::string& field) {
        if (scene.camera) return; // the first one
        const tinygltf::Camera& in = element(model.cameras, index, field, "camera");
        if (in.type != "perspective" || !(in.perspective.zfar > in.perspective.znear))
            refuse(field, "this engine takes a perspective camera with a finite zfar");
        agaa::Camera camera;
        camera.yfov = float(in.perspective.yfov);
        camera.znear = float(in.perspective.znear);
        camera.zfar = float(in.perspective.zfar);
        // The node's frame without its scale: -Z is the view axis.
        const glm::vec3 back = glm::normalize(glm::vec3(world[2]));
        const glm::vec3 right = glm::normalize(glm::cross(glm::vec3(world[1]), back));
        camera.view = glm::inverse(glm::mat4(glm::vec4(right, 0.0f), glm::vec4(glm::cross(back, right), 0.0f),
                                             glm::vec4(back, 0.0f), glm::vec4(glm::vec3(world[3]), 1.0f)));
        scene.camera = camera;
    }

    // Depth-first from the scene's roots, children in order.
    void import() {
        const int sceneIndex = model.defaultScene >= 0 ? model.defaultScene : 0;
        if (size_t(sceneIndex) >= model.scenes.size()) refuse("scenes", "none");
        struct Pending {
            int node;
            glm::mat4 parent;
        };
        const std::vector<int>& roots = model.scenes[size_t(sceneIndex)].nodes;
        for (int root : roots) {
            std::vector<Pending> stack{{root, glm::mat4(1.0f)}};
            while (!stack.empty()) {
                const Pending p = stack.back();
                stack.pop_back();
                const tinygltf::Node& node = element(model.nodes, p.node, "scenes", "node");
                const std::string field = "nodes[" + std::to_string(p.node) + "]";
                const glm::mat4 world = p.parent * local(node);
                if (node.mesh >= 0) addMesh(element(model.meshes, node.mesh, field, "mesh"), world, field);
                if (const auto light = node.extensions.find("KHR_lights_punctual");
                    light != node.extensions.end())
                    addLight(light->second.Has("light") && light->second.Get("light").IsInt()
                                 ? light->second.Get("light").GetNumberAsInt()
                                 : -1,
                             world, field + ".extensions.KHR_lights_punctual.light");
                if (node.camera >= 0) addCamera(node.camera, world, field);
                for (size_t c = node.children.size(); c-- > 0;)
                    stack.push_back({node.children[c], world});
            }
        }
        if (!castsSaid) // the convention this engine shares with the module's loader: the sun casts
            for (agaa::Light& light : scene.lights)
                if (light.type == agaa::LightType::Directional) {
                    light.castsShadows = true;
                    break;
                }
        if (!scene.camera) refuse("cameras", "none; this engine renders the file's first camera");
    }
};

HostScene importGltf(const std::string& path) {
    tinygltf::Model model;
    tinygltf::TinyGLTF loader;
    std::string error, warning;
    const bool binary = path.size() > 4 && path.substr(path.size() - 4) == ".glb";
    const bool ok = binary ? loader.LoadBinaryFromFile(&model, &error, &warning, path)
                           : loader.LoadASCIIFromFile(&model, &error, &warning, path);
    if (!ok) throw std::runtime_error(path + ": not a glTF file this engine can read: " + error);
    Importer importer{model, path, {}};
    importer.import();
    return std::move(importer.scene);
}

vk::Image hostImage(vk::Device& device, uint32_t size, const char* name) {
    return vk::createImage(device,
                           {VK_FORMAT_R32G32B32A32_SFLOAT, size, size, 1, 1, VK_SAMPLE_COUNT_1_BIT,
                            VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                            VK_IMAGE_VIEW_TYPE_2D},
                           name);
}

} // namespace

int main(int argc, char** argv) {
    if (argc != 6 && !(argc == 8 && std::string(argv[6]) == "--compare")) {
        std::fprintf(stderr,
                     "usage: host_engine FILE.gltf METHOD SIZE OUT.exr SHADER_DIR [--compare REF.exr]\n");
        return 2;
    }
    const std::string file = argv[1], method = argv[2], out = argv[4], shaders = argv[5];
    const int sizeArg = std::atoi(argv[3]);
    if (sizeArg < 1 || sizeArg > 4096) {
        std::fprintf(stderr, "host_engine: SIZE '%s' is not an integer in 1..4096\n", argv[3]);
        return 2;
    }
    const auto size = uint32_t(sizeArg);
    try {
        HostScene content = importGltf(file);
        vk::DeviceOptions options;
        options.validation = true;
        vk::Device device(options);

        const agaa::TechniqueContent traits{
            host_engine::hostTraits(content.mesh, content.lights, "host:" + file)};
        const host_engine::HostProgramFiles programs = host_engine::readHostPrograms(shaders);
        host_engine::HostGeometry drawer(device, std::move(content.mesh), programs.programs());
        const eng::frame::GpuEnvironment noEnvironment(device, nullptr); // the stand-in: black, skipped
        const agaa::EnvironmentBindings environment = agaa::environmentBindings(noEnvironment);

        agaa::MethodSettings settings; // the one accumulation build this engine's shaders have
        settings.agaa.atomics = agaa::AggregateAtomics::Bits32;
        settings.agaa.subgroupReduction = agaa::SubgroupReduction::Off;
        std::unique_ptr<agaa::Technique> technique = agaa::createTechnique(method, device, traits, settings);

        // One frame into this engine's own command buffer: the display into its colour image,
        // the HDR into another, then its own copy of the HDR out.
        eng::frame::ViewSettings view;
        view.width = view.height = size;
        view.cameraOverride = content.camera;
        // This engine's own images and readback, released on every path out.
        struct Owned {
            vk::Device& device;
            vk::Image color, hdr;
            vk::Buffer readback;
            ~Owned() {
                vkDeviceWaitIdle(device.device());
                vk::destroyImage(device, color);
                vk::destroyImage(device, hdr);
                vk::destroyBuffer(device, readback);
            }
        } owned{device, hostImage(device, size, "host.color"), hostImage(device, size, "host.hdr"),
                eng::frame::createReadbackBuffer(device, size, size, VK_FORMAT_R32G32B32A32_SFLOAT,
                                                 "host.readback")};
        const vk::Image &color = owned.color, &hdr = owned.hdr;
        const vk::Buffer& readback = owned.readback;
        const auto target = [&](const vk::Image& image, std::optional<eng::rg::Use> final) {
            return agaa::HostTarget{
                {image.image, image.view, image.view, {VK_FORMAT_R32G32B32A32_SFLOAT, size, size}},
                std::nullopt,
                final};
        };
        agaa::FrameRecorder recorder(device, traits);
        device.submitAndWait([&](VkCommandBuffer cmd) {
            recorder.record(
                cmd, *technique, view,
                {target(color, std::nullopt), std::nullopt, target(hdr, eng::rg::Use::TransferSrc)}, 0,
                {&drawer, &environment, nullptr});
            VkBufferImageCopy region{};
            region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
            region.imageExtent = {size, size, 1};
            // The state the frame left it in, as its target named it (engine/graph/use.h's table).
            const VkImageLayout layout = eng::rg::useInfo(eng::rg::Use::TransferSrc).layout;
            vkCmdCopyImageToBuffer(cmd, hdr.image, layout, readback.buffer, 1, &region);
        });
        vk::invalidateBuffer(device, readback);
        eng::io::ImageF image = eng::io::makeImage(size, size);
        std::memcpy(image.rgba.data(), readback.mapped, image.rgba.size() * sizeof(float));
        eng::io::writeExr(out, image);

        int status = 0;
        if (argc == 8) {
            const eng::io::ImageF reference = eng::io::readExr(argv[7]);
            const double rmse = eng::io::rmse(eng::io::toneMapped(image), eng::io::toneMapped(reference));
            std::printf("host_engine: %s on %s at %ux%u: display RMSE %.3g against %s\n", method.c_str(),
                        file.c_str(), size, size, rmse, argv[7]);
            status = rmse <= 1e-4 ? 0 : 1;
        }
        const uint32_t errors = device.validationErrors();
        std::printf("host_engine: wrote %s, %u validation error(s)\n", out.c_str(), errors);
        return errors == 0 ? status : 1;
    } catch (const std::runtime_error& e) { // the file, the shaders or the method: bad input
        std::fprintf(stderr, "host_engine: %s\n", e.what());
        return 2;
    } catch (const std::invalid_argument& e) {
        std::fprintf(stderr, "host_engine: %s\n", e.what());
        return 2;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "host_engine: %s\n", e.what());
        return 1;
    }
}
