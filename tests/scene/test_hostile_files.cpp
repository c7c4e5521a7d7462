// Inputs a hostile user found to crash or abort the loader (issue 19's table), each now refused
// with a SceneError naming the file, or loaded with bounded warnings. Every case here crashed,
// aborted or printed an internal message before its fix.

#include "engine/scene/gltf_loader.h"
#include "engine/scene/leaf_texture.h"

#include "gltf_test_model.h"
#include "loader_test_support.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <string>

namespace eng::scene {
namespace {

using test::TestModel;

using test::loadError;

using HostileFiles = test::TempDirTest;

// A chain of children 25,000 deep is a valid file: the node walk used to recurse per level.
TEST_F(HostileFiles, NodeChainTwentyFiveThousandDeepLoads) {
    TestModel m = test::makeTriangleModel();
    int parent = 0; // the triangle's node is the scene root
    for (int i = 0; i < 25000; ++i) {
        parent = m.addNode(parent);
        m.model.nodes[static_cast<size_t>(parent)].name = "link"; // tinygltf writes an empty node as null
    }
    const auto path = m_dir / "deep.gltf";
    test::writeModel(m.model, path);
    Scene scene = loadGltf(path);
    EXPECT_EQ(scene.triangleCount(), 1u);
}

// The same file text with a JSON value nested `depth` levels deep spliced in as the root's
// "extras" (arrays or objects).
std::string withNestedExtras(const std::string& gltf, size_t depth, bool objects) {
    std::string open, close;
    for (size_t i = 0; i < depth; ++i) {
        open += objects ? "{\"a\":" : "[";
        close += objects ? "}" : "]";
    }
    const std::string value = open + (objects ? "0" : "") + close;
    const size_t brace = gltf.find('{');
    return gltf.substr(0, brace + 1) + "\"extras\":" + value + "," + gltf.substr(brace + 1);
}

TEST_F(HostileFiles, JsonNestedTwentyThousandDeepIsRefusedNamingTheLimit) {
    const TestModel m = test::makeTriangleModel();
    const auto valid = m_dir / "valid.gltf";
    test::writeModel(m.model, valid);
    const std::string text = test::readFile(valid);
    for (bool objects : {false, true}) {
        const auto path = m_dir / (objects ? "objects.gltf" : "arrays.gltf");
        test::writeFile(path, withNestedExtras(text, 20000, objects));
        const std::string message = loadError(path);
        EXPECT_NE(message.find(path.string()), std::string::npos) << message;
        EXPECT_NE(message.find("JSON nests deeper than 512 levels"), std::string::npos) << message;
        EXPECT_NE(message.find("allowed: up to 512"), std::string::npos) << message;
    }
    // 100 levels is legal JSON and a legal glTF: it loads.
    const auto shallow = m_dir / "shallow.gltf";
    test::writeFile(shallow, withNestedExtras(text, 100, false));
    EXPECT_EQ(loadGltf(shallow).triangleCount(), 1u);
}

// A PNG whose zlib stream is corrupt: stb_image fails without a reason (NULL), which was appended
// to a std::string. Data URI, external file and GLB bufferView all take that path.
std::string corruptPng() {
    std::vector<uint8_t> png = encodePng(makeLeafImage(16));
    std::string bytes(png.begin(), png.end());
    const size_t idat = bytes.find("IDAT");
    EXPECT_NE(idat, std::string::npos) << "test setup: the PNG must have an IDAT chunk";
    for (size_t i = idat + 6; i < std::min(bytes.size() - 12, idat + 40); ++i)
        bytes[i] = static_cast<char>(0xFF); // past the zlib header: the deflate blocks
    return bytes;
}

std::string base64(const std::string& in) {
    static const char* k = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (size_t i = 0; i < in.size(); i += 3) {
        uint32_t v = uint8_t(in[i]) << 16;
        if (i + 1 < in.size()) v |= uint8_t(in[i + 1]) << 8;
        if (i + 2 < in.size()) v |= uint8_t(in[i + 2]);
        out += k[(v >> 18) & 63];
        out += k[(v >> 12) & 63];
        out += i + 1 < in.size() ? k[(v >> 6) & 63] : '=';
        out += i + 2 < in.size() ? k[v & 63] : '=';
    }
    return out;
}

// The triangle model's .gltf text with one image (given as JSON), a texture and a material on it.
std::string texturedTriangleText(const std::filesystem::path& dir, const nlohmann::json& image) {
    const TestModel m = test::makeTriangleModel();
    const auto valid = dir / "valid.gltf";
    test::writeModel(m.model, valid);
    nlohmann::json j = nlohmann::json::parse(test::readFile(valid));
    j["images"] = nlohmann::json::array({image});
    j["textures"] = nlohmann::json::array({{{"source", 0}}});
    j["materials"] =
        nlohmann::json::array({{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}});
    j["meshes"][0]["primitives"][0]["material"] = 0;
    return j.dump();
}

TEST_F(HostileFiles, CorruptPngTextureIsRefusedNamingTheImage) {
    const std::string png = corruptPng();
    const auto dataUri = m_dir / "datauri.gltf";
    test::writeFile(dataUri, texturedTriangleText(m_dir, {{"uri", "data:image/png;base64," + base64(png)}}));
    test::writeFile(m_dir / "leaf.png", png);
    const auto file = m_dir / "external.gltf";
    test::writeFile(file, texturedTriangleText(m_dir, {{"uri", "leaf.png"}}));
    // GLB: the image in a bufferView of the binary chunk.
    TestModel c = test::makeTriangleModel();
    tinygltf::Image view;
    view.mimeType = "image/png";
    view.name = "leaf";
    view.bufferView = c.addBufferView(png.data(), png.size());
    c.model.images.push_back(view);
    tinygltf::Texture texture;
    texture.source = 0;
    c.model.textures.push_back(texture);
    tinygltf::Material material;
    material.pbrMetallicRoughness.baseColorTexture.index = 0;
    c.model.materials.push_back(material);
    c.model.meshes[0].primitives[0].material = 0;
    const auto glb = m_dir / "bufferview.glb";
    test::writeModel(c.model, glb);
    for (const auto& path : {dataUri, file, glb}) {
        const std::string message = loadError(path);
        EXPECT_NE(message.find(path.string()), std::string::npos) << message;
        EXPECT_NE(message.find("images[0]"), std::string::npos) << message;
        EXPECT_NE(message.find("cannot decode"), std::string::npos) << message;
    }
    EXPECT_NE(loadError(file).find("'leaf.png'"), std::string::npos)
        << "an external image is named by its URI";
    EXPECT_NE(loadError(dataUri).find("images[0] (embedded)"), std::string::npos)
        << "a data URI is not echoed";
}

TEST_F(HostileFiles, ADirectoryIsNotASceneOrABuffer) {
    const auto dir = m_dir / "folder.gltf";
    std::filesystem::create_directories(dir);
    const std::string message = loadError(dir);
    EXPECT_NE(message.find("is a directory"), std::string::npos) << message;

    std::filesystem::create_directories(m_dir / "buffers");
    const auto path = m_dir / "dirbuffer.gltf";
    test::writeFile(path, R"({"asset":{"version":"2.0"},
        "buffers":[{"uri":"buffers","byteLength":36}],
        "bufferViews":[{"buffer":0,"byteLength":36}],
        "accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3"}],
        "meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],
        "nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}]})");
    const std::string bufferMessage = loadError(path);
    EXPECT_NE(bufferMessage.find("is a directory"), std::string::npos) << bufferMessage;
    EXPECT_EQ(bufferMessage.find("bad_alloc"), std::string::npos) << bufferMessage;
}

TEST_F(HostileFiles, NumberOverflowIsAReadableJsonError) {
    const auto path = m_dir / "overflow.gltf";
    test::writeFile(
        path,
        R"({"asset":{"version":"2.0"},"nodes":[{"translation":[1e400,0,0]}],"scenes":[{"nodes":[0]}]})");
    const std::string message = loadError(path);
    EXPECT_NE(message.find(path.string()), std::string::npos) << message;
    EXPECT_NE(message.find("invalid JSON"), std::string::npos) << message;
    EXPECT_NE(message.find("1e400"), std::string::npos) << "the message must quote the number: " << message;
    EXPECT_EQ(message.find("[json.exception"), std::string::npos) << "no library-internal ids: " << message;
}

TEST_F(HostileFiles, ARootNodeRepeatedThousandsOfTimesGivesAFewWarningsAndACount) {
    TestModel m = test::makeTriangleModel();
    std::vector<int>& roots = m.model.scenes[0].nodes;
    roots.assign(3000, roots.front());
    const auto path = m_dir / "repeated.gltf";
    test::writeModel(m.model, path);
    Scene scene = loadGltf(path);
    EXPECT_EQ(scene.triangleCount(), 1u);
    std::string all;
    for (const std::string& w : scene.stats.warnings)
        all += w + "\n";
    ASSERT_LE(scene.stats.warnings.size(), 6u) << "2,999 warnings of one kind must be summarised:\n" << all;
    bool counted = false;
    for (const std::string& w : scene.stats.warnings)
        counted |= w.find("2994 more warnings like") != std::string::npos;
    EXPECT_TRUE(counted) << "the summary must say how many were left out";
}

TEST_F(HostileFiles, AFailedDataUriIsNotEchoedWhole) {
    const auto path = m_dir / "baduri.gltf";
    const std::string junk(200000, '!'); // not base64
    test::writeFile(path,
                    R"({"asset":{"version":"2.0"},"buffers":[{"uri":"data:application/octet-stream;base64,)" +
                        junk + R"(","byteLength":36}],"scenes":[{"nodes":[]}]})");
    const std::string message = loadError(path);
    EXPECT_NE(message.find(path.string()), std::string::npos) << message.substr(0, 400);
    EXPECT_LT(message.size(), 2000u) << "the message must not carry the whole URI";
}

TEST(Warnings, SummariseKeepsTheFirstOfEachKindInOrder) {
    std::vector<std::string> w = {"a: nodes[1] ignored", "b: other", "a: nodes[2] ignored",
                                  "a: nodes[3] ignored"};
    summariseWarnings(w, 1);
    ASSERT_EQ(w.size(), 3u);
    EXPECT_EQ(w[0], "a: nodes[1] ignored");
    EXPECT_EQ(w[1], "b: other");
    EXPECT_EQ(w[2], "2 more warnings like: a: nodes[#] ignored");
}

} // namespace
} // namespace eng::scene
