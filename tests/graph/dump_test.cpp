// The DOT and JSON dumps: complete, culled passes marked, barriers readable.

#include "graph_test_support.h"

#include <nlohmann/json.hpp>

namespace eng::rg::test {
namespace {

// prepass -> lighting -> imported hdr; "debugView" reads depth but writes only an unread transient.
void buildSmallFrame(Graph& graph) {
    Texture hdr = graph.importTexture("hdr", fakeTexture(), std::nullopt, Use::SampledFragment);
    Texture depth;
    graph.addPass<NoData>(
        "prepass", PassKind::Graphics,
        [&](Builder& b, NoData&) {
            depth = b.write(b.create("depth", colorDesc(VK_FORMAT_D32_SFLOAT)), Use::DepthStencilWrite);
        },
        nullptr);
    graph.addPass<NoData>(
        "debugView", PassKind::Compute,
        [&](Builder& b, NoData&) {
            b.read(depth, Use::SampledCompute);
            b.write(b.create("debug", colorDesc()), Use::StorageImageWriteCompute);
        },
        nullptr);
    graph.addPass<NoData>(
        "lighting", PassKind::Compute,
        [&](Builder& b, NoData&) {
            b.read(depth, Use::SampledCompute);
            hdr = b.write(hdr, Use::StorageImageWriteCompute);
        },
        nullptr);
}

// The DOT line declaring the first node (pass, or resource version) labelled `name`.
std::string nodeLine(const std::string& dot, const std::string& name) {
    const size_t at = dot.find("label=\"" + name + "\\n");
    if (at == std::string::npos) return {};
    const size_t begin = dot.rfind('\n', at) + 1;
    return dot.substr(begin, dot.find('\n', at) - begin);
}

TEST(GraphDump, DotContainsEveryPassAndMarksCulled) {
    Graph graph;
    buildSmallFrame(graph);
    graph.compile();
    const std::string dot = graph.dumpDot();
    EXPECT_EQ(dot.rfind("digraph", 0), 0u) << "a Graphviz digraph";
    for (const char* pass : {"prepass", "debugView", "lighting"})
        EXPECT_NE(nodeLine(dot, pass), "") << "every pass, culled or not, has a node: " << pass;
    EXPECT_NE(nodeLine(dot, "debugView").find("culled"), std::string::npos) << nodeLine(dot, "debugView");
    EXPECT_NE(nodeLine(dot, "debugView").find("grey"), std::string::npos) << "culled passes are greyed";
    EXPECT_EQ(nodeLine(dot, "lighting").find("culled"), std::string::npos)
        << "executed passes are not marked";
    EXPECT_NE(nodeLine(dot, "prepass").find("shape=box"), std::string::npos) << "passes are boxes";
    EXPECT_NE(nodeLine(dot, "hdr").find("peripheries=2"), std::string::npos)
        << "imported resources are styled apart from transients: " << nodeLine(dot, "hdr");
    EXPECT_EQ(nodeLine(dot, "depth").find("peripheries=2"), std::string::npos) << nodeLine(dot, "depth");
    EXPECT_NE(dot.find("shape=ellipse"), std::string::npos) << "resources are ellipses";
    EXPECT_NE(dot.find("[label=\"SampledCompute\""), std::string::npos) << "edges carry the use";
}

TEST(GraphDump, JsonListsCulledPassesAndBarriers) {
    Graph graph;
    buildSmallFrame(graph);
    graph.compile();
    const nlohmann::json json = nlohmann::json::parse(graph.dumpJson());

    ASSERT_TRUE(json.contains("culled"));
    EXPECT_EQ(json["culled"], nlohmann::json::array({"debugView"})) << "the top-level list of culled passes";
    ASSERT_EQ(json["passes"].size(), 3u) << "culled passes stay in the dump";
    const nlohmann::json& debugView = json["passes"][1];
    EXPECT_EQ(debugView["name"], "debugView");
    EXPECT_TRUE(debugView["culled"].get<bool>());
    EXPECT_TRUE(debugView["order"].is_null()) << "a culled pass has no execution index";

    const nlohmann::json& lighting = json["passes"][2];
    EXPECT_EQ(lighting["order"], 1) << "lighting runs second";
    EXPECT_EQ(lighting["reads"][0]["resource"], "depth");
    EXPECT_EQ(lighting["writes"][0]["resource"], "hdr");
    bool foundDepthTransition = false;
    for (const nlohmann::json& barrier : lighting["barriers"]) {
        if (barrier["resource"] != "depth") continue;
        foundDepthTransition = true;
        EXPECT_EQ(barrier["oldLayout"], "VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL");
        EXPECT_EQ(barrier["newLayout"], "VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL");
        EXPECT_EQ(barrier["dstStage"], "VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT");
        EXPECT_EQ(barrier["srcAccess"], "VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT");
        EXPECT_EQ(barrier["srcStage"],
                  "VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT|VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT")
            << "multi-bit masks are readable, '|'-joined";
    }
    EXPECT_TRUE(foundDepthTransition) << "lighting's barriers include the depth transition";

    bool foundDepthResource = false;
    for (const nlohmann::json& resource : json["resources"]) {
        if (resource["name"] == "depth") {
            foundDepthResource = true;
            EXPECT_EQ(resource["firstPass"], "prepass");
            EXPECT_EQ(resource["lastPass"], "lighting");
            EXPECT_EQ(resource["usage"],
                      "VK_IMAGE_USAGE_SAMPLED_BIT|VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT");
            EXPECT_FALSE(resource["imported"].get<bool>());
            EXPECT_EQ(resource["desc"]["format"], "VK_FORMAT_D32_SFLOAT");
        }
        if (resource["name"] == "debug") {
            EXPECT_TRUE(resource["firstPass"].is_null()) << "never realised";
        }
        if (resource["name"] == "hdr") {
            EXPECT_TRUE(resource["imported"].get<bool>());
        }
    }
    EXPECT_TRUE(foundDepthResource);
    ASSERT_EQ(json["finalBarriers"].size(), 1u) << "hdr asks to end in SampledFragment";
    EXPECT_EQ(json["finalBarriers"][0]["newLayout"], "VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL");
}

TEST(GraphDump, DumpsWorkBeforeCompile) {
    Graph graph;
    buildSmallFrame(graph);
    EXPECT_NE(graph.dumpDot().find("debugView"), std::string::npos)
        << "a graph that fails to compile must still be dumpable";
    const nlohmann::json json = nlohmann::json::parse(graph.dumpJson());
    EXPECT_FALSE(json["compiled"].get<bool>());
    EXPECT_TRUE(json["culled"].empty()) << "nothing is known to be culled before compile()";
}

TEST(GraphDump, JsonShowsEachPassesRenderPass) {
    Graph graph;
    Texture depth, color;
    graph.addGraphics<NoData>(
        "raster",
        [&](Builder& b, NoData&) {
            Attachment load;
            load.load = VK_ATTACHMENT_LOAD_OP_LOAD;
            load.store = VK_ATTACHMENT_STORE_OP_DONT_CARE;
            depth = b.depthStencil(b.create("depth", colorDesc(VK_FORMAT_D32_SFLOAT)), Use::DepthStencilWrite,
                                   load);
            color = b.color(b.create("color", colorDesc()));
        },
        nullptr);
    graph.addCompute<NoData>(
        "resolve", [&](Builder& b, NoData&) { b.read(color, Use::SampledCompute); }, nullptr);
    graph.markOutput(color);
    graph.compile();
    const nlohmann::json json = nlohmann::json::parse(graph.dumpJson());
    const nlohmann::json& raster = json["passes"][0]["renderPass"];
    ASSERT_TRUE(raster.is_object()) << json["passes"][0].dump();
    EXPECT_EQ(raster["width"], 64);
    EXPECT_EQ(raster["height"], 32);
    EXPECT_EQ(raster["layers"], 1);
    ASSERT_EQ(raster["colors"].size(), 1u);
    EXPECT_EQ(raster["colors"][0]["resource"], "color");
    EXPECT_EQ(raster["colors"][0]["load"], "CLEAR");
    EXPECT_EQ(raster["colors"][0]["store"], "STORE");
    EXPECT_EQ(raster["depth"]["resource"], "depth");
    EXPECT_EQ(raster["depth"]["load"], "LOAD");
    EXPECT_EQ(raster["depth"]["store"], "DONT_CARE");
    EXPECT_TRUE(json["passes"][1]["renderPass"].is_null()) << "a compute pass has no render pass";
}

} // namespace
} // namespace eng::rg::test
