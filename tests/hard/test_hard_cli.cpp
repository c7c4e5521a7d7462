// agaa-render on malformed glTF files: refused with exit code 2 and a message naming the file
// and the field, or repaired with a warning and rendered; never a NaN image.

#include "malformed_models.h"

#include <gtest/gtest.h>

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <filesystem>

namespace {

namespace fs = std::filesystem;
using agaa::hard::Corruption;

struct CliRun {
    int exitCode = -1;
    std::string output; // stdout and stderr
};

CliRun agaaRender(const std::string& args) {
    CliRun r;
    const std::string cmd = std::string(AGAA_RENDER_EXE) + " " + args + " 2>&1";
    FILE* pipe = popen(cmd.c_str(), "r");
    if (!pipe) return r;
    std::array<char, 512> buf{};
    while (fgets(buf.data(), buf.size(), pipe))
        r.output += buf.data();
    const int status = pclose(pipe);
    r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return r;
}

fs::path writeModel(Corruption c, const std::string& name) {
    const fs::path dir = fs::temp_directory_path() / "agaa_hard_cli";
    fs::create_directories(dir);
    const fs::path file = dir / name;
    tinygltf::Model m = agaa::hard::malformedModel(c);
    tinygltf::TinyGLTF writer;
    EXPECT_TRUE(writer.WriteGltfSceneToFile(&m, file.string(), true, true, true, false)) << file;
    return file;
}

TEST(HardCli, MalformedScenesExitWithCode2NamingFileAndField) {
    struct Case {
        Corruption corruption;
        const char* file;
        const char* field;
    };
    for (const Case& c : {Case{Corruption::NanPosition, "nan_position.gltf", "POSITION"},
                          Case{Corruption::IndexOutOfRange, "index_out_of_range.gltf", "indices"}}) {
        const fs::path file = writeModel(c.corruption, c.file);
        const CliRun r = agaaRender("--scene " + file.string() + " --width 16 --height 16 --out " +
                                    (file.parent_path() / "out").string());
        EXPECT_EQ(r.exitCode, 2) << c.file << ": bad input must exit with 2\n" << r.output;
        EXPECT_NE(r.output.find(c.file), std::string::npos) << "the message names the file:\n" << r.output;
        EXPECT_NE(r.output.find(c.field), std::string::npos)
            << "the message names the field " << c.field << ":\n"
            << r.output;
    }
}

TEST(HardCli, ZeroNormalsAreRepairedWithAWarningAndRender) {
    const fs::path file = writeModel(Corruption::ZeroNormals, "zero_normals.gltf");
    const fs::path out = file.parent_path() / "zero_normals";
    const CliRun r = agaaRender("--scene " + file.string() +
                                " --method agaa --width 16 --height 16 --validate --out " + out.string());
    EXPECT_EQ(r.exitCode, 0)
        << "a repairable file renders (exit 1 would mean a NaN image or a validation error)\n"
        << r.output;
    EXPECT_NE(r.output.find("warning:"), std::string::npos) << "the repair is logged:\n" << r.output;
    EXPECT_NE(r.output.find("NORMAL"), std::string::npos) << "the warning names the attribute:\n" << r.output;
    EXPECT_TRUE(fs::exists(out.string() + ".exr")) << "the frame was written";
}

TEST(HardCli, HardScenesRenderFromTheCommandLine) {
    const fs::path out = fs::temp_directory_path() / "agaa_hard_cli" / "light_inside";
    const CliRun r = agaaRender(
        "--builtin hard-light-inside --method agaa --width 17 --height 13 --validate --out " + out.string());
    EXPECT_EQ(r.exitCode, 0) << r.output;
}

} // namespace
