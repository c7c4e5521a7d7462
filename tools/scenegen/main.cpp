// scenegen: writes the procedural test scenes (engine/scene/scenegen.h) to disk.
//   scenegen --kind NAME [--seed N] [--density F] --out FILE.gltf|FILE.glb
//   scenegen --all --out-dir DIR [--seed N] [--density F]
//   scenegen --list | --help
// Exit codes: 0 success, 1 write or generation failure, 2 bad arguments.

#include "engine/scene/scenegen.h"
#include "tools/scenes/adversarial_scenes.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

namespace {

constexpr int kExitOk = 0;
constexpr int kExitFailure = 1;
constexpr int kExitUsage = 2;

struct Args {
    std::optional<std::string> kind;
    bool all = false;
    bool list = false;
    bool help = false;
    std::optional<std::filesystem::path> out;
    std::optional<std::filesystem::path> outDir;
    eng::scene::GenOptions gen;
};

struct UsageError {
    std::string message;
};

std::string kindList() {
    std::string s;
    for (const std::string& k : eng::scene::sceneKinds()) {
        s += (s.empty() ? "" : ", ") + k;
    }
    s += "; adversarial (tests/hard):";
    for (const std::string& k : eng::scene::hardSceneKinds())
        s += " " + k;
    return s;
}

void printHelp() {
    std::cout
        << "usage:\n"
           "  scenegen --kind NAME [--seed N] [--density F] --out FILE.gltf|FILE.glb\n"
           "  scenegen --all --out-dir DIR [--seed N] [--density F]   (writes DIR/NAME.gltf for every kind)\n"
           "  scenegen --list\n"
           "  scenegen --help\n"
           "kinds: "
        << kindList()
        << "\n"
           "--seed: unsigned 32-bit integer (default 1)\n"
           "--density: number in (0, "
        << eng::scene::kMaxDensity
        << "] scaling strand, leaf and bar counts (default 1)\n"
           ".gltf output embeds buffers and images as data URIs; .glb is one binary file.\n";
}

Args parse(int argc, char** argv) {
    Args args;
    for (int i = 1; i < argc; ++i) {
        const std::string flag = argv[i];
        auto value = [&]() -> std::string {
            if (i + 1 >= argc) {
                throw UsageError{flag + ": missing value"};
            }
            return argv[++i];
        };
        if (flag == "--kind") {
            const std::string kind = value();
            const auto kinds = eng::scene::sceneKinds();
            if (std::find(kinds.begin(), kinds.end(), kind) == kinds.end() &&
                !eng::scene::isHardSceneKind(kind)) {
                throw UsageError{"--kind: '" + kind + "' is not one of " + kindList()};
            }
            args.kind = kind;
        } else if (flag == "--seed") {
            const std::string v = value();
            uint32_t seed = 0;
            const auto [end, ec] = std::from_chars(v.data(), v.data() + v.size(), seed);
            if (ec != std::errc() || end != v.data() + v.size()) {
                throw UsageError{"--seed: '" + v + "' is not an unsigned 32-bit integer (0..4294967295)"};
            }
            args.gen.seed = seed;
        } else if (flag == "--density") {
            const std::string v = value();
            float density = 0.0f;
            const auto [end, ec] = std::from_chars(v.data(), v.data() + v.size(), density);
            if (ec != std::errc() || end != v.data() + v.size() || !std::isfinite(density) ||
                density <= 0.0f || density > eng::scene::kMaxDensity) {
                throw UsageError{"--density: '" + v + "' is not a number in (0, " +
                                 std::to_string(eng::scene::kMaxDensity) + "]"};
            }
            args.gen.density = density;
        } else if (flag == "--out") {
            args.out = value();
        } else if (flag == "--out-dir") {
            args.outDir = value();
        } else if (flag == "--all") {
            args.all = true;
        } else if (flag == "--list") {
            args.list = true;
        } else if (flag == "--help" || flag == "-h") {
            args.help = true;
        } else {
            throw UsageError{flag +
                             ": unknown flag; allowed: --kind, --seed, --density, --out, --all, --out-dir, "
                             "--list, --help"};
        }
    }
    if (args.help || args.list) {
        return args;
    }
    if (args.all == args.kind.has_value()) {
        throw UsageError{"--kind/--all: give exactly one of --kind NAME or --all"};
    }
    if (args.kind) {
        if (!args.out) {
            throw UsageError{"--out: required with --kind (FILE.gltf or FILE.glb)"};
        }
        const std::string ext = args.out->extension().string();
        if (ext != ".gltf" && ext != ".glb") {
            throw UsageError{"--out: '" + args.out->string() + "' must end in .gltf or .glb"};
        }
    }
    if (args.all && !args.outDir) {
        throw UsageError{"--out-dir: required with --all"};
    }
    return args;
}

bool writeScene(const std::string& kind, const eng::scene::GenOptions& gen,
                const std::filesystem::path& out) {
    const tinygltf::Model model = eng::scene::generateTestScene(kind, gen);
    const bool binary = out.extension() == ".glb";
    tinygltf::TinyGLTF writer;
    // embedImages: images live in the buffer already; embedBuffers: data URIs
    // for .gltf so the file is self-contained (ignored for buffer 0 of a .glb).
    const bool ok = writer.WriteGltfSceneToFile(&model, out.string(), true, true, !binary, binary);
    if (!ok) {
        std::cerr << "scenegen: " << out.string() << ": write failed\n";
        return false;
    }
    std::cout << out.string() << "\n";
    return true;
}

} // namespace

int main(int argc, char** argv) {
    Args args;
    try {
        args = parse(argc, argv);
    } catch (const UsageError& e) {
        std::cerr << "scenegen: " << e.message << "\n(run scenegen --help for usage)\n";
        return kExitUsage;
    }
    if (args.help) {
        printHelp();
        return kExitOk;
    }
    if (args.list) {
        for (const std::string& k : eng::scene::sceneKinds()) {
            std::cout << k << "\n";
        }
        for (const std::string& k : eng::scene::hardSceneKinds())
            std::cout << k << " (adversarial)\n";
        return kExitOk;
    }
    try {
        if (args.kind) {
            return writeScene(*args.kind, args.gen, *args.out) ? kExitOk : kExitFailure;
        }
        std::error_code ec;
        std::filesystem::create_directories(*args.outDir, ec);
        if (ec) {
            std::cerr << "scenegen: --out-dir: cannot create '" << args.outDir->string()
                      << "': " << ec.message() << "\n";
            return kExitFailure;
        }
        bool ok = true;
        for (const std::string& k : eng::scene::sceneKinds()) {
            ok = writeScene(k, args.gen, *args.outDir / (k + ".gltf")) && ok;
        }
        return ok ? kExitOk : kExitFailure;
    } catch (const std::exception& e) {
        std::cerr << "scenegen: " << e.what() << "\n";
        return kExitFailure;
    }
}
