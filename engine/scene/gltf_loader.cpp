#include "engine/scene/gltf_loader.h"

#include "engine/scene/gltf_accessor.h"
#include "engine/scene/gltf_lights_cameras.h"
#include "engine/scene/gltf_materials.h"
#include "engine/scene/mesh_repair.h"

#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <map>
#include <string_view>

namespace eng::scene {

namespace {

bool isFinite(const glm::vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

std::string vecText(const glm::vec3& v) {
    return "(" + std::to_string(v.x) + ", " + std::to_string(v.y) + ", " + std::to_string(v.z) + ")";
}

// Node-local transform: matrix if given, else T * R * S (glTF 2.0 section 3.5.3).
glm::mat4 localMatrix(const tinygltf::Node& node, const std::string& source, const std::string& field,
                      std::vector<std::string>& warnings) {
    auto checkFinite = [&](const std::vector<double>& v, const char* name) {
        for (double d : v) {
            if (!std::isfinite(d)) {
                throw SceneError(source + ": " + field + "." + name + ": not finite");
            }
        }
    };
    if (!node.matrix.empty()) {
        if (node.matrix.size() != 16) {
            warnings.push_back(source + ": " + field + ".matrix: needs 16 numbers, has " +
                               std::to_string(node.matrix.size()) + "; using identity");
            return glm::mat4(1.0f);
        }
        checkFinite(node.matrix, "matrix");
        glm::dmat4 m = glm::make_mat4(node.matrix.data()); // glTF stores column-major, as glm does
        return glm::mat4(m);
    }
    glm::dvec3 t(0.0), s(1.0);
    glm::dquat r(1.0, 0.0, 0.0, 0.0);
    if (node.translation.size() == 3) {
        checkFinite(node.translation, "translation");
        t = glm::make_vec3(node.translation.data());
    } else if (!node.translation.empty()) {
        warnings.push_back(source + ": " + field + ".translation: needs 3 numbers; ignored");
    }
    if (node.rotation.size() == 4) {
        checkFinite(node.rotation, "rotation");
        // glTF quaternions are (x, y, z, w); glm's constructor takes w first.
        r = glm::dquat(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);
        const double len = glm::length(r);
        if (!(len > 1e-12)) {
            warnings.push_back(source + ": " + field + ".rotation: zero quaternion; using identity");
            r = glm::dquat(1.0, 0.0, 0.0, 0.0);
        } else {
            r = r / len;
        }
    } else if (!node.rotation.empty()) {
        warnings.push_back(source + ": " + field + ".rotation: needs 4 numbers; ignored");
    }
    if (node.scale.size() == 3) {
        checkFinite(node.scale, "scale");
        s = glm::make_vec3(node.scale.data());
    } else if (!node.scale.empty()) {
        warnings.push_back(source + ": " + field + ".scale: needs 3 numbers; ignored");
    }
    glm::dmat4 m = glm::mat4_cast(r);
    m[0] *= s.x;
    m[1] *= s.y;
    m[2] *= s.z;
    m[3] = glm::dvec4(t, 1.0);
    return glm::mat4(m);
}

class GltfConverter {
  public:
    GltfConverter(const tinygltf::Model& model, const std::string& source)
        : m_model(model), m_source(source) {
        m_scene.source = source;
    }

    // The extensions this loader implements. glTF 2.0 (section 3.12): an asset whose
    // extensionsRequired names any other must not be loaded (it would render wrong without a
    // word: KHR_draco_mesh_compression, KHR_texture_basisu, KHR_texture_transform...); an optional
    // one in extensionsUsed is ignored with a warning.
    static constexpr const char* kSupportedExtensions[] = {"KHR_lights_punctual",
                                                           "KHR_materials_emissive_strength",
                                                           "KHR_mesh_quantization", "KHR_texture_transform"};

    // glTF 2.0 section 3.2 (asset): the major version is the file format's; another major version
    // (glTF 1.0 or a future 3.x) cannot be read as 2.0.
    void checkVersion() {
        const std::string& v = m_model.asset.version;
        const size_t dot = v.find('.');
        if (v.empty()) return; // tinygltf refuses a missing asset.version already
        if (v.substr(0, dot) != "2")
            throw SceneError(m_source + ": asset.version: '" + boundedName(v) +
                             "' is not a glTF 2.x asset (supported: 2.0)");
    }

    void checkExtensions() {
        std::string supported;
        for (const char* e : kSupportedExtensions)
            supported += std::string(supported.empty() ? "" : ", ") + e;
        auto isSupported = [](const std::string& name) {
            for (const char* e : kSupportedExtensions)
                if (name == e) return true;
            return false;
        };
        for (size_t i = 0; i < m_model.extensionsRequired.size(); ++i) {
            const std::string& name = m_model.extensionsRequired[i];
            if (!isSupported(name))
                throw SceneError(m_source + ": extensionsRequired[" + std::to_string(i) + "]: '" +
                                 boundedName(name) + "' is not supported (supported: " + supported + ")");
        }
        for (const std::string& name : m_model.extensionsUsed)
            if (!isSupported(name))
                m_scene.stats.warnings.push_back(m_source + ": extensionsUsed: '" + boundedName(name) +
                                                 "' is not supported; its data is ignored");
    }

    // A name from the file, cut to a readable length (a hostile file may hold megabytes).
    static std::string boundedName(const std::string& name) {
        constexpr size_t kMax = 64;
        return name.size() <= kMax ? name : name.substr(0, kMax) + "...";
    }

    Scene run() {
        checkVersion();
        checkExtensions();
        convertMaterials(m_model, m_source, m_scene);
        collectNodes();
        for (const NodeInstance& instance : m_instances) {
            addMesh(instance);
        }
        computeBounds();
        std::vector<LightRecord> lights;
        for (const NodeInstance& instance : m_instances) {
            LightRecord record;
            if (readNodeLight(m_model, m_source, instance.node, instance.world, m_scene, record)) {
                lights.push_back(record);
            }
            Camera camera;
            if (readNodeCamera(m_model, m_source, instance.node, instance.world, m_scene, camera)) {
                m_scene.cameras.push_back(camera);
            }
        }
        resolveShadowCasters(lights, m_scene);
        finishCameras(m_scene);
        if (m_scene.materials.empty()) {
            defaultMaterial();
        }
        return std::move(m_scene);
    }

  private:
    struct NodeInstance {
        int node = -1;
        glm::mat4 world{1.0f};
    };

    void warn(const std::string& what) { m_scene.stats.warnings.push_back(m_source + ": " + what); }

    void collectNodes() {
        std::vector<int> roots;
        if (!m_model.scenes.empty()) {
            int sceneIndex = m_model.defaultScene;
            if (sceneIndex < 0) {
                sceneIndex = 0;
            } else if (static_cast<size_t>(sceneIndex) >= m_model.scenes.size()) {
                throw SceneError(m_source + ": scene: " + std::to_string(sceneIndex) + " out of range (" +
                                 std::to_string(m_model.scenes.size()) + " scenes)");
            }
            roots = m_model.scenes[static_cast<size_t>(sceneIndex)].nodes;
        } else {
            // No scenes: glTF leaves it to the application; draw every root node.
            std::vector<bool> isChild(m_model.nodes.size(), false);
            for (const tinygltf::Node& node : m_model.nodes) {
                for (int c : node.children) {
                    if (c >= 0 && static_cast<size_t>(c) < isChild.size()) {
                        isChild[static_cast<size_t>(c)] = true;
                    }
                }
            }
            for (size_t i = 0; i < m_model.nodes.size(); ++i) {
                if (!isChild[i]) {
                    roots.push_back(static_cast<int>(i));
                }
            }
            if (!m_model.nodes.empty()) {
                warn("scenes: none defined; using every root node");
            }
        }
        m_visited.assign(m_model.nodes.size(), false);
        for (size_t i = 0; i < roots.size(); ++i) {
            visit(roots[i], glm::mat4(1.0f), "scenes.nodes[" + std::to_string(i) + "]");
        }
    }

    // Depth-first over the node hierarchy with an explicit stack: a valid file may nest nodes
    // tens of thousands deep (a chain of children), which recursion would turn into a stack
    // overflow. Children are visited in order; a node is visited once (m_visited), so a cycle or
    // a second parent ends at that check.
    void visit(int rootIndex, const glm::mat4& rootParent, const std::string& rootReferrer) {
        struct Pending {
            int node;
            glm::mat4 parent;
            std::string referrer;
        };
        std::vector<Pending> stack{{rootIndex, rootParent, rootReferrer}};
        while (!stack.empty()) {
            Pending p = std::move(stack.back());
            stack.pop_back();
            if (p.node < 0 || static_cast<size_t>(p.node) >= m_model.nodes.size()) {
                throw SceneError(m_source + ": " + p.referrer + ": node " + std::to_string(p.node) +
                                 " out of range (" + std::to_string(m_model.nodes.size()) + " nodes)");
            }
            const std::string field = "nodes[" + std::to_string(p.node) + "]";
            if (m_visited[static_cast<size_t>(p.node)]) {
                warn(p.referrer + ": " + field + " already visited (a cycle or a second parent); ignored");
                continue;
            }
            m_visited[static_cast<size_t>(p.node)] = true;
            const tinygltf::Node& node = m_model.nodes[static_cast<size_t>(p.node)];
            const glm::mat4 world = p.parent * localMatrix(node, m_source, field, m_scene.stats.warnings);
            m_instances.push_back({p.node, world});
            for (size_t c = node.children.size(); c-- > 0;) {
                stack.push_back({node.children[c], world, field + ".children[" + std::to_string(c) + "]"});
            }
        }
    }

    uint32_t defaultMaterial() {
        if (m_defaultMaterial == std::numeric_limits<uint32_t>::max()) {
            Material material;
            material.name = "default";
            material.metallicFactor = 0.0f;
            material.roughnessFactor = 0.5f;
            m_scene.materials.push_back(material);
            m_defaultMaterial = static_cast<uint32_t>(m_scene.materials.size() - 1);
        }
        return m_defaultMaterial;
    }

    void addMesh(const NodeInstance& instance) {
        const tinygltf::Node& node = m_model.nodes[static_cast<size_t>(instance.node)];
        if (node.mesh < 0) {
            return;
        }
        if (static_cast<size_t>(node.mesh) >= m_model.meshes.size()) {
            throw SceneError(m_source + ": nodes[" + std::to_string(instance.node) + "].mesh: mesh " +
                             std::to_string(node.mesh) + " out of range (" +
                             std::to_string(m_model.meshes.size()) + " meshes)");
        }
        const tinygltf::Mesh& mesh = m_model.meshes[static_cast<size_t>(node.mesh)];
        for (size_t p = 0; p < mesh.primitives.size(); ++p) {
            addPrimitive(mesh.primitives[p],
                         "meshes[" + std::to_string(node.mesh) + "].primitives[" + std::to_string(p) + "]",
                         instance.world);
        }
    }

    void addPrimitive(const tinygltf::Primitive& prim, const std::string& ctx, const glm::mat4& world) {
        const int mode = prim.mode < 0 ? TINYGLTF_MODE_TRIANGLES : prim.mode;
        if (mode != TINYGLTF_MODE_TRIANGLES) {
            warn(ctx + ".mode: " + std::to_string(mode) + " is not TRIANGLES (4); primitive skipped");
            return;
        }
        const auto attribute = [&](const char* name) {
            const auto it = prim.attributes.find(name);
            return it == prim.attributes.end() ? -1 : it->second;
        };
        const int posIndex = attribute("POSITION");
        if (posIndex < 0) {
            warn(ctx + ".attributes: no POSITION; primitive skipped");
            return;
        }
        uint32_t material = 0;
        if (prim.material < 0) {
            material = defaultMaterial();
        } else if (static_cast<size_t>(prim.material) >= m_model.materials.size()) {
            throw SceneError(m_source + ": " + ctx + ".material: material " + std::to_string(prim.material) +
                             " out of range (" + std::to_string(m_model.materials.size()) + " materials)");
        } else {
            material = static_cast<uint32_t>(prim.material);
        }

        AccessorExpect posExpect; // float, or quantized integers (KHR_mesh_quantization)
        posExpect.allowNormalizedInts = true;
        posExpect.allowPlainInts = true;
        const AccessorReader positions(m_model, m_source, posIndex, posExpect, ctx + ".attributes.POSITION");
        const size_t count = positions.count();
        if (count == 0) {
            warn(positions.field() + ".count: 0 vertices; primitive skipped");
            return;
        }

        std::vector<Vertex> vertices(count);
        const glm::mat3 linear(world);
        const glm::mat3 normalMatrix = glm::transpose(glm::inverse(linear));
        const float det = glm::determinant(linear);
        const float handedness = det < 0.0f ? -1.0f : 1.0f;
        for (size_t i = 0; i < count; ++i) {
            const glm::vec3 p = positions.vec3(i);
            if (!isFinite(p)) {
                throw SceneError(m_source + ": " + positions.field() + ": POSITION element " +
                                 std::to_string(i) + " is " + vecText(p) + ", not finite");
            }
            vertices[i].position = glm::vec3(world * glm::vec4(p, 1.0f));
            if (!isFinite(vertices[i].position)) {
                throw SceneError(m_source + ": " + positions.field() + ": POSITION element " +
                                 std::to_string(i) + " is not finite after the node transform");
            }
        }

        const int normalIndex = attribute("NORMAL");
        const int tangentIndex = attribute("TANGENT");
        auto checkCount = [&](const AccessorReader& r, const char* name) {
            if (r.count() != count) {
                throw SceneError(m_source + ": " + r.field() + ".count: " + name + " has " +
                                 std::to_string(r.count()) + " elements but POSITION (accessors[" +
                                 std::to_string(posIndex) + "]) has " + std::to_string(count));
            }
        };
        if (normalIndex >= 0) {
            AccessorExpect e;
            e.allowNormalizedInts = true;
            const AccessorReader normals(m_model, m_source, normalIndex, e, ctx + ".attributes.NORMAL");
            checkCount(normals, "NORMAL");
            for (size_t i = 0; i < count; ++i) {
                // Inverse-transpose keeps normals perpendicular under non-uniform
                // scale; repairNormals renormalises and fixes zero ones.
                vertices[i].normal = normalMatrix * normals.vec3(i);
            }
        }
        if (tangentIndex >= 0) {
            AccessorExpect e;
            e.type = TINYGLTF_TYPE_VEC4;
            e.allowNormalizedInts = true;
            const AccessorReader tangents(m_model, m_source, tangentIndex, e, ctx + ".attributes.TANGENT");
            checkCount(tangents, "TANGENT");
            for (size_t i = 0; i < count; ++i) {
                const glm::vec4 t = tangents.vec4(i);
                // A mirroring transform reverses cross(N, T), so the bitangent
                // sign must flip for B = w * cross(N, T) to stay the mapped B.
                vertices[i].tangent =
                    glm::vec4(linear * glm::vec3(t), (t.w < 0.0f ? -1.0f : 1.0f) * handedness);
            }
        }
        // TEXCOORD_0 and TEXCOORD_1: float, normalized or plain integers; a non-finite value is 0.
        auto readUvSet = [&](const char* name, glm::vec2 Vertex::*member) {
            const int index = attribute(name);
            if (index < 0) return;
            AccessorExpect e;
            e.type = TINYGLTF_TYPE_VEC2;
            e.allowNormalizedInts = true;
            e.allowPlainInts = true;
            const AccessorReader uvs(m_model, m_source, index, e, ctx + ".attributes." + name);
            checkCount(uvs, name);
            size_t bad = 0;
            for (size_t i = 0; i < count; ++i) {
                const glm::vec2 uv = uvs.vec2(i);
                if (std::isfinite(uv.x) && std::isfinite(uv.y))
                    vertices[i].*member = uv;
                else
                    ++bad;
            }
            if (bad > 0)
                warn(uvs.field() + ": " + std::to_string(bad) + " " + name + " values not finite; set to 0");
        };
        readUvSet("TEXCOORD_0", &Vertex::uv);
        readUvSet("TEXCOORD_1", &Vertex::uv1);
        // COLOR_0 (glTF 2.0 3.7.2.1): VEC3 or VEC4, float or normalized unsigned byte/short, linear,
        // multiplying the base colour.
        if (const int colorIndex = attribute("COLOR_0"); colorIndex >= 0) {
            AccessorExpect e;
            e.type = m_model.accessors[size_t(colorIndex)].type == TINYGLTF_TYPE_VEC3 ? TINYGLTF_TYPE_VEC3
                                                                                      : TINYGLTF_TYPE_VEC4;
            e.allowNormalizedInts = true;
            const AccessorReader colors(m_model, m_source, colorIndex, e, ctx + ".attributes.COLOR_0");
            checkCount(colors, "COLOR_0");
            size_t bad = 0;
            for (size_t i = 0; i < count; ++i) {
                glm::vec4 c = e.type == TINYGLTF_TYPE_VEC3 ? glm::vec4(colors.vec3(i), 1.0f) : colors.vec4(i);
                bool ok = true;
                for (int k = 0; k < 4; ++k)
                    ok = ok && std::isfinite(c[k]) && c[k] >= 0.0f && c[k] <= 1.0f;
                if (!ok) {
                    ++bad;
                    for (int k = 0; k < 4; ++k)
                        c[k] = std::isfinite(c[k]) ? std::clamp(c[k], 0.0f, 1.0f) : 1.0f;
                }
                vertices[i].color = c;
            }
            if (bad > 0)
                warn(colors.field() + ": " + std::to_string(bad) +
                     " COLOR_0 values outside [0, 1] or not finite; clamped (non-finite: 1)");
        }

        std::vector<uint32_t> indices = readIndices(m_model, m_source, prim, ctx, count, posIndex);
        if (indices.size() % 3 != 0) {
            warn(ctx + ".indices: " + std::to_string(indices.size()) +
                 " indices is not a multiple of 3; the last partial triangle is dropped");
            indices.resize(indices.size() - indices.size() % 3);
        }
        if (det < 0.0f) {
            // A mirroring transform turns counter-clockwise front faces clockwise.
            for (size_t t = 0; t + 2 < indices.size(); t += 3) {
                std::swap(indices[t + 1], indices[t + 2]);
            }
        }

        const uint32_t dropped = dropDegenerateTriangles(vertices, indices);
        if (dropped > 0) {
            m_scene.stats.degenerateTrianglesDropped += dropped;
            warn(ctx + ": " + std::to_string(dropped) + " degenerate triangles dropped");
        }
        if (indices.empty()) {
            warn(ctx + ": no triangles left; primitive skipped");
            return;
        }
        if (normalIndex < 0) {
            makeFlatNormals(vertices, indices);
            ++m_scene.stats.primitivesWithFlatNormals;
        } else if (const uint32_t repaired = repairNormals(vertices, indices); repaired > 0) {
            warn(ctx + ".attributes.NORMAL: " + std::to_string(repaired) +
                 " zero-length or non-finite normals replaced by the face normal");
        }
        if (tangentIndex < 0) {
            generateTangents(vertices, indices, attribute("TEXCOORD_0") >= 0);
        } else if (const uint32_t repaired = repairTangents(vertices); repaired > 0) {
            warn(ctx + ".attributes.TANGENT: " + std::to_string(repaired) + " unusable tangents replaced");
        }
        append(vertices, indices, material, ctx);
    }

    void append(const std::vector<Vertex>& vertices, const std::vector<uint32_t>& indices, uint32_t material,
                const std::string& ctx) {
        const size_t base = m_scene.vertices.size();
        if (base + vertices.size() > std::numeric_limits<uint32_t>::max() ||
            m_scene.indices.size() + indices.size() > std::numeric_limits<uint32_t>::max()) {
            throw SceneError(m_source + ": " + ctx + ": the scene exceeds 2^32 vertices or indices");
        }
        Draw draw;
        draw.firstIndex = static_cast<uint32_t>(m_scene.indices.size());
        draw.indexCount = static_cast<uint32_t>(indices.size());
        draw.material = material;
        m_scene.vertices.insert(m_scene.vertices.end(), vertices.begin(), vertices.end());
        for (uint32_t i : indices) {
            m_scene.indices.push_back(static_cast<uint32_t>(base) + i);
        }
        m_scene.draws.push_back(draw);
    }

    void computeBounds() {
        if (m_scene.vertices.empty()) {
            return; // stays the zero box; the default camera copes
        }
        Bounds b;
        b.min = glm::vec3(std::numeric_limits<float>::max());
        b.max = glm::vec3(-std::numeric_limits<float>::max());
        for (const Vertex& v : m_scene.vertices) {
            b.min = glm::min(b.min, v.position);
            b.max = glm::max(b.max, v.position);
        }
        m_scene.bounds = b;
    }

    const tinygltf::Model& m_model;
    std::string m_source;
    Scene m_scene;
    std::vector<NodeInstance> m_instances;
    std::vector<bool> m_visited;
    uint32_t m_defaultMaterial = std::numeric_limits<uint32_t>::max();
};

std::string lowerExtension(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext;
}

std::string trimmed(std::string s) {
    while (!s.empty() && (s.back() == '\n' || s.back() == '\r' || s.back() == ' ')) {
        s.pop_back();
    }
    return s;
}

} // namespace

Scene loadGltfModel(const tinygltf::Model& model, const std::string& sourceName) {
    return GltfConverter(model, sourceName).run();
}

namespace {

// Deeper JSON than this is refused before tinygltf parses it: its JSON parser recurses per level
// and overflows the stack on an array nested 20,000 deep. No glTF needs a tenth of this.
constexpr size_t kMaxJsonNesting = 512;

// The JSON text of a .gltf file, or of a .glb's first (JSON) chunk; empty when the GLB header is
// malformed (tinygltf then reports that).
std::string_view jsonText(const std::vector<char>& bytes, bool glb) {
    if (!glb) return {bytes.data(), bytes.size()};
    auto u32 = [&](size_t at) {
        uint32_t v = 0;
        std::memcpy(&v, bytes.data() + at, 4);
        return v;
    };
    if (bytes.size() < 20 || u32(16) != 0x4E4F534Au) return {}; // chunk type 'JSON'
    const size_t length = u32(12);
    if (length > bytes.size() - 20) return {};
    return {bytes.data() + 20, length};
}

void checkJsonNesting(const std::string& source, std::string_view json) {
    size_t depth = 0;
    bool inString = false, escaped = false;
    for (size_t i = 0; i < json.size(); ++i) {
        const char ch = json[i];
        if (inString) {
            if (escaped)
                escaped = false;
            else if (ch == '\\')
                escaped = true;
            else if (ch == '"')
                inString = false;
        } else if (ch == '"') {
            inString = true;
        } else if (ch == '[' || ch == '{') {
            if (++depth > kMaxJsonNesting)
                throw SceneError(source + ": JSON nests deeper than " + std::to_string(kMaxJsonNesting) +
                                 " levels (at byte " + std::to_string(i) + "); refused (allowed: up to " +
                                 std::to_string(kMaxJsonNesting) + ")");
        } else if ((ch == ']' || ch == '}') && depth > 0) {
            --depth;
        }
    }
}

// tinygltf reads a buffer or image URI with an ifstream, which opens a directory on Linux and
// then asks for an absurd size (std::bad_alloc): refuse anything but a regular file, by name.
bool readRegularFile(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* user) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) {
        if (err != nullptr)
            *err +=
                "'" + path + "' is " +
                (std::filesystem::is_directory(path, ec) ? "a directory" : "not a readable regular file") +
                ", not a buffer or image file\n";
        return false;
    }
    return tinygltf::ReadWholeFile(out, err, path, user);
}

// A message for people: lines no longer than a few hundred characters (a failed data URI would
// otherwise be echoed whole, megabytes of base64) and nlohmann's internal exception ids removed.
std::string readable(std::string text) {
    const std::string prefix = "[json.exception.";
    for (size_t at; (at = text.find(prefix)) != std::string::npos;) {
        const size_t end = text.find("] ", at);
        if (end == std::string::npos) break;
        text.replace(at, end + 2 - at, "invalid JSON: ");
    }
    constexpr size_t kMaxLine = 240;
    std::string out;
    size_t start = 0;
    while (start <= text.size()) {
        size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        std::string line = text.substr(start, end - start);
        if (line.size() > kMaxLine)
            line = line.substr(0, kMaxLine) + "... (" + std::to_string(line.size() - kMaxLine) +
                   " more characters)";
        out += (out.empty() ? "" : "\n") + line;
        start = end + 1;
    }
    return out;
}

} // namespace

// Many warnings of one kind (one root node listed 5,000 times) become a few and a count: the same
// text once its numbers are masked counts as one kind.
void summariseWarnings(std::vector<std::string>& warnings, size_t keepPerKind) {
    std::map<std::string, size_t> seen;
    std::vector<std::string> kept;
    std::vector<std::string> kinds; // in order of first appearance
    for (const std::string& w : warnings) {
        std::string kind; // every run of digits becomes one '#'
        for (char ch : w)
            if (!std::isdigit(static_cast<unsigned char>(ch)))
                kind += ch;
            else if (kind.empty() || kind.back() != '#')
                kind += '#';
        size_t& n = seen[kind];
        if (n == 0) kinds.push_back(kind);
        if (n++ < keepPerKind) kept.push_back(readable(w));
    }
    for (const std::string& kind : kinds)
        if (seen[kind] > keepPerKind)
            kept.push_back(std::to_string(seen[kind] - keepPerKind) + " more warnings like: " +
                           readable(kind.substr(0, std::min<size_t>(kind.size(), 160))));
    warnings = std::move(kept);
}

Scene loadGltf(const std::filesystem::path& path) {
    const std::string source = path.string();
    const std::string ext = lowerExtension(path);
    if (ext != ".gltf" && ext != ".glb") {
        throw SceneError(source + ": extension '" + ext + "' is not .gltf or .glb");
    }
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) {
        throw SceneError(source + ": is a directory, not a .gltf or .glb file");
    }
    std::vector<char> bytes;
    {
        std::ifstream probe(path, std::ios::binary);
        if (!probe) {
            throw SceneError(source + ": cannot open the file for reading");
        }
        bytes.assign(std::istreambuf_iterator<char>(probe), std::istreambuf_iterator<char>());
    }
    checkJsonNesting(source, jsonText(bytes, ext == ".glb"));
    tinygltf::TinyGLTF gltf;
    // Our decoder always yields RGBA8 and reports failures per image.
    gltf.SetImageLoader(&decodeImageRgba8, nullptr);
    gltf.SetFsCallbacks({&tinygltf::FileExists, &tinygltf::ExpandFilePath, &readRegularFile,
                         &tinygltf::WriteWholeFile, nullptr});
    tinygltf::Model model;
    std::string err;
    std::string warn;
    bool ok = false;
    try {
        ok = ext == ".glb" ? gltf.LoadBinaryFromFile(&model, &err, &warn, source)
                           : gltf.LoadASCIIFromFile(&model, &err, &warn, source);
    } catch (const std::exception& e) {
        // tinygltf's JSON layer may throw on malformed input instead of reporting.
        ok = false;
        err += e.what();
    }
    if (!ok) {
        throw SceneError(
            source + ": " +
            (err.empty() ? std::string("tinygltf failed without a message") : readable(trimmed(err))));
    }
    Scene scene = loadGltfModel(model, source);
    if (!warn.empty()) {
        scene.stats.warnings.push_back(source + ": " + trimmed(warn));
    }
    summariseWarnings(scene.stats.warnings);
    return scene;
}

} // namespace eng::scene
