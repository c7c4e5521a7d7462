#pragma once
// Our scene's triangles in the host sample's layout (samples/host_engine/host_content.h), as the
// host's own importer makes them of the same content: what the node tests and the package test's
// consumer compare the host's frames with our scene's on. Header-only, on installed headers alone.

#include "engine/scene/scene.h"
#include "samples/host_engine/host_content.h"

#include <algorithm>
#include <stdexcept>

namespace agaa::test {

using host_engine::HostGeometry;
using host_engine::HostMesh;
using host_engine::hostTraits;

// Our scene's triangles in the host's layout, as the host's importer would make them of the same
// content.
inline HostMesh hostMesh(const eng::scene::Scene& scene) {
    HostMesh mesh;
    for (const eng::scene::Vertex& v : scene.vertices)
        mesh.vertices.push_back(
            {{v.position.x, v.position.y, v.position.z}, {v.normal.x, v.normal.y, v.normal.z}});
    for (const eng::scene::Draw& d : scene.draws) {
        if (d.indexCount == 0) continue;
        const auto first = scene.indices.begin() + d.firstIndex;
        const auto [lo, hi] = std::minmax_element(first, first + d.indexCount);
        if (*hi - *lo > 0xFFFFu) throw std::invalid_argument("a draw spans more than 16-bit indices reach");
        const eng::scene::Material& m = scene.materials.at(d.material);
        host_engine::HostDraw draw{
            uint32_t(mesh.indices.size()), d.indexCount, int32_t(*lo), {}, m.doubleSided};
        draw.material = {{m.baseColorFactor.r, m.baseColorFactor.g, m.baseColorFactor.b, m.roughnessFactor},
                         {m.metallicFactor, 0.0f, 0.0f, 0.0f}};
        for (uint32_t i = 0; i < d.indexCount; ++i)
            mesh.indices.push_back(uint16_t(first[i] - *lo));
        mesh.draws.push_back(draw);
    }
    return mesh;
}

} // namespace agaa::test
