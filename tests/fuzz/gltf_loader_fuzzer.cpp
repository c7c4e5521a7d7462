// libFuzzer target: any bytes as a .gltf or .glb file (GLB when they start with its magic).
// The loader's contract (engine/scene/gltf_loader.h): every input either loads into a scene whose
// geometry is finite, or is refused with a SceneError. Anything else (a crash, a sanitizer report,
// another exception, a non-finite position) is a finding. External URIs resolve next to the
// input file, in a folder of its own, so a mutated input can name files that do not exist.

#include "engine/scene/gltf_loader.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

namespace {

std::filesystem::path inputFolder() {
    static const std::filesystem::path folder = [] {
        std::filesystem::path p =
            std::filesystem::temp_directory_path() / ("agaa-fuzz-" + std::to_string(::getpid()));
        std::filesystem::create_directories(p);
        return p;
    }();
    return folder;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const bool glb = size >= 4 && data[0] == 'g' && data[1] == 'l' && data[2] == 'T' && data[3] == 'F';
    const std::filesystem::path path = inputFolder() / (glb ? "input.glb" : "input.gltf");
    {
        std::ofstream f(path, std::ios::binary | std::ios::trunc);
        f.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    }
    try {
        eng::scene::Scene scene = eng::scene::loadGltf(path);
        for (const eng::scene::Vertex& v : scene.vertices)
            if (!std::isfinite(v.position.x) || !std::isfinite(v.position.y) ||
                !std::isfinite(v.position.z)) {
                std::fprintf(stderr, "finding: a non-finite position reached the scene\n");
                std::abort();
            }
        for (uint32_t i : scene.indices)
            if (i >= scene.vertices.size()) {
                std::fprintf(stderr, "finding: an index past the vertices reached the scene\n");
                std::abort();
            }
    } catch (const eng::scene::SceneError&) {
        // refused with a message: the contract
    }
    return 0;
}
