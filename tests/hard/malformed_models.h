#pragma once
// Malformed variants of the hard-flat scene, made by corrupting the glTF buffer the way a broken
// exporter would: for the loader tests and the agaa-render exit-code tests.

#include "tools/scenes/adversarial_scenes.h"

#include <tiny_gltf.h>

#include <cstring>
#include <limits>
#include <string>

namespace agaa::hard {

enum class Corruption { NanPosition, InfPosition, IndexOutOfRange, ZeroNormals, NanNormals };

// Bytes of accessor `index` of the first primitive's attribute `name` ("indices" for the index accessor).
inline unsigned char* accessorBytes(tinygltf::Model& m, const std::string& name) {
    const tinygltf::Primitive& prim = m.meshes.at(0).primitives.at(0);
    const int accessor = name == "indices" ? prim.indices : prim.attributes.at(name);
    const tinygltf::Accessor& a = m.accessors.at(size_t(accessor));
    const tinygltf::BufferView& v = m.bufferViews.at(size_t(a.bufferView));
    return m.buffers.at(size_t(v.buffer)).data.data() + v.byteOffset + a.byteOffset;
}

inline tinygltf::Model malformedModel(Corruption c) {
    tinygltf::Model m = eng::scene::generateHardScene("hard-flat");
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    const tinygltf::Accessor& normals =
        m.accessors.at(size_t(m.meshes[0].primitives[0].attributes.at("NORMAL")));
    switch (c) {
    case Corruption::NanPosition:
        std::memcpy(accessorBytes(m, "POSITION") + 4, &nan, 4);
        break;
    case Corruption::InfPosition:
        std::memcpy(accessorBytes(m, "POSITION"), &inf, 4);
        break;
    case Corruption::IndexOutOfRange: {
        const uint32_t big = 1000000u;
        std::memcpy(accessorBytes(m, "indices") + 4, &big, 4);
        break;
    }
    case Corruption::ZeroNormals:
        std::memset(accessorBytes(m, "NORMAL"), 0, normals.count * 12);
        break;
    case Corruption::NanNormals:
        for (size_t i = 0; i < normals.count * 3; ++i)
            std::memcpy(accessorBytes(m, "NORMAL") + 4 * i, &nan, 4);
        break;
    }
    return m;
}

} // namespace agaa::hard
