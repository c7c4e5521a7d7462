#pragma once
// Validated reads of glTF accessors. Every index (accessor, bufferView, buffer)
// and every byte range is checked before a byte is touched, so a hostile file
// ends in a SceneError naming the field instead of an out-of-bounds read.

#include <tiny_gltf.h>

#include <glm/glm.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace eng::scene {

// What the caller expects of an accessor; the reader refuses anything else.
struct AccessorExpect {
    int type = TINYGLTF_TYPE_VEC3; // TINYGLTF_TYPE_*
    bool allowFloat = true;
    bool allowNormalizedInts = false; // ubyte/byte/ushort/short with normalized = true
    bool allowPlainInts = false;      // integer types without normalized (quantized positions, indices)
    bool allowUnsignedInt = false;    // only indices may be u32
};

class AccessorReader {
  public:
    // context names the reference in the error messages, e.g.
    // "meshes[0].primitives[1].attributes.NORMAL".
    AccessorReader(const tinygltf::Model& model, const std::string& source, int accessorIndex,
                   const AccessorExpect& expect, const std::string& context);

    size_t count() const { return m_count; }
    int accessorIndex() const { return m_accessorIndex; }
    // "accessors[3]" - the prefix for messages about this accessor's elements.
    std::string field() const;

    // Component c of element i, converted to float per the glTF normalisation rules.
    float component(size_t element, int c) const;
    glm::vec2 vec2(size_t i) const { return {component(i, 0), component(i, 1)}; }
    glm::vec3 vec3(size_t i) const { return {component(i, 0), component(i, 1), component(i, 2)}; }
    glm::vec4 vec4(size_t i) const {
        return {component(i, 0), component(i, 1), component(i, 2), component(i, 3)};
    }
    uint32_t index(size_t i) const; // integer scalars, not normalised

  private:
    [[noreturn]] void fail(const std::string& what) const;
    // The element's bytes: a sparse substitute, the bufferView's, or nullptr (zeros).
    const uint8_t* elementAddress(size_t i) const;
    void readSparse(const tinygltf::Model& model, const tinygltf::Accessor& accessor, size_t elementSize);

    std::string m_source;
    std::string m_context;
    int m_accessorIndex = -1;
    const uint8_t* m_data = nullptr; // nullptr: no bufferView, all elements are zero (glTF rule)
    size_t m_count = 0;
    size_t m_stride = 0;
    int m_componentType = 0;
    int m_componentSize = 0;
    int m_components = 0;
    bool m_normalized = false;
    // Sparse accessors (glTF 2.0 3.6.2.3): the substituted element indices, strictly increasing,
    // and the address of each one's replacement value (tightly packed).
    std::vector<uint32_t> m_sparseIndices;
    std::vector<const uint8_t*> m_sparseValues;
};

// Reads the indices of a primitive, or 0..vertexCount-1 when it has none.
// Throws when an index is not below vertexCount, naming both accessors.
std::vector<uint32_t> readIndices(const tinygltf::Model& model, const std::string& source,
                                  const tinygltf::Primitive& primitive, const std::string& context,
                                  size_t vertexCount, int positionAccessor);

// Bytes of a bufferView, validated against its buffer ("images[2].bufferView" style context).
std::vector<uint8_t> bufferViewBytes(const tinygltf::Model& model, const std::string& source,
                                     int bufferViewIndex, const std::string& context);

const char* typeName(int type);

} // namespace eng::scene
