#include "engine/scene/gltf_accessor.h"

#include "engine/scene/scene_error.h"

#include <algorithm>
#include <cstring>
#include <limits>

namespace eng::scene {

namespace {

int componentSize(int componentType) {
    switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
        return 2;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
        return 4;
    default:
        return 0;
    }
}

int componentCount(int type) {
    switch (type) {
    case TINYGLTF_TYPE_SCALAR:
        return 1;
    case TINYGLTF_TYPE_VEC2:
        return 2;
    case TINYGLTF_TYPE_VEC3:
        return 3;
    case TINYGLTF_TYPE_VEC4:
        return 4;
    case TINYGLTF_TYPE_MAT2:
        return 4;
    case TINYGLTF_TYPE_MAT3:
        return 9;
    case TINYGLTF_TYPE_MAT4:
        return 16;
    default:
        return 0;
    }
}

const char* componentTypeName(int componentType) {
    switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
        return "BYTE";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return "UNSIGNED_BYTE";
    case TINYGLTF_COMPONENT_TYPE_SHORT:
        return "SHORT";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
        return "UNSIGNED_SHORT";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
        return "UNSIGNED_INT";
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
        return "FLOAT";
    default:
        return "unknown";
    }
}

// A bufferView's byte range inside its buffer, after checking both indices and
// that offset + length does not overflow or pass the end of the buffer.
struct ViewRange {
    const uint8_t* data = nullptr;
    size_t length = 0;
    size_t stride = 0;
};

ViewRange resolveView(const tinygltf::Model& model, const std::string& source, int viewIndex,
                      const std::string& referrer) {
    if (viewIndex < 0 || static_cast<size_t>(viewIndex) >= model.bufferViews.size()) {
        throw SceneError(source + ": " + referrer + ": bufferView " + std::to_string(viewIndex) +
                         " out of range (" + std::to_string(model.bufferViews.size()) + " bufferViews)");
    }
    const tinygltf::BufferView& view = model.bufferViews[static_cast<size_t>(viewIndex)];
    const std::string field = "bufferViews[" + std::to_string(viewIndex) + "]";
    if (view.buffer < 0 || static_cast<size_t>(view.buffer) >= model.buffers.size()) {
        throw SceneError(source + ": " + field + ".buffer: buffer " + std::to_string(view.buffer) +
                         " out of range (" + std::to_string(model.buffers.size()) + " buffers)");
    }
    const tinygltf::Buffer& buffer = model.buffers[static_cast<size_t>(view.buffer)];
    if (view.byteOffset > buffer.data.size() || view.byteLength > buffer.data.size() - view.byteOffset) {
        throw SceneError(source + ": " + field + ".byteLength: bytes [" + std::to_string(view.byteOffset) +
                         ", " + std::to_string(view.byteOffset + view.byteLength) +
                         ") pass the end of buffers[" + std::to_string(view.buffer) + "] (" +
                         std::to_string(buffer.data.size()) + " bytes)");
    }
    return {buffer.data.data() + view.byteOffset, view.byteLength, view.byteStride};
}

} // namespace

const char* typeName(int type) {
    switch (type) {
    case TINYGLTF_TYPE_SCALAR:
        return "SCALAR";
    case TINYGLTF_TYPE_VEC2:
        return "VEC2";
    case TINYGLTF_TYPE_VEC3:
        return "VEC3";
    case TINYGLTF_TYPE_VEC4:
        return "VEC4";
    case TINYGLTF_TYPE_MAT2:
        return "MAT2";
    case TINYGLTF_TYPE_MAT3:
        return "MAT3";
    case TINYGLTF_TYPE_MAT4:
        return "MAT4";
    default:
        return "unknown";
    }
}

AccessorReader::AccessorReader(const tinygltf::Model& model, const std::string& source, int accessorIndex,
                               const AccessorExpect& expect, const std::string& context)
    : m_source(source), m_context(context), m_accessorIndex(accessorIndex) {
    if (accessorIndex < 0 || static_cast<size_t>(accessorIndex) >= model.accessors.size()) {
        throw SceneError(source + ": " + context + ": accessor " + std::to_string(accessorIndex) +
                         " out of range (" + std::to_string(model.accessors.size()) + " accessors)");
    }
    const tinygltf::Accessor& accessor = model.accessors[static_cast<size_t>(accessorIndex)];
    const std::string f = field();

    if (accessor.type != expect.type) {
        fail(f + ".type: " + context + " needs " + typeName(expect.type) + " but the accessor is " +
             typeName(accessor.type));
    }
    m_componentType = accessor.componentType;
    m_componentSize = componentSize(m_componentType);
    m_components = componentCount(accessor.type);
    m_normalized = accessor.normalized;
    const bool isFloat = m_componentType == TINYGLTF_COMPONENT_TYPE_FLOAT;
    const bool isU32 = m_componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
    const bool ok =
        m_componentSize != 0 &&
        ((isFloat && expect.allowFloat) || (isU32 && expect.allowUnsignedInt) ||
         (!isFloat && !isU32 &&
          ((m_normalized && expect.allowNormalizedInts) || (!m_normalized && expect.allowPlainInts))));
    if (!ok) {
        fail(f + ".componentType: " + componentTypeName(m_componentType) +
             (m_normalized ? " (normalized)" : "") + " is not allowed for " + context);
    }
    m_count = accessor.count;
    const size_t elementSize = static_cast<size_t>(m_componentSize) * static_cast<size_t>(m_components);
    if (accessor.sparse.isSparse) readSparse(model, accessor, elementSize);
    if (accessor.bufferView < 0) {
        // glTF: an accessor without a bufferView reads as zeros (before any sparse substitution).
        m_data = nullptr;
        m_stride = elementSize;
        return;
    }
    const ViewRange view = resolveView(model, source, accessor.bufferView, f + ".bufferView");
    m_stride = view.stride != 0 ? view.stride : elementSize;
    if (m_stride < elementSize) {
        fail("bufferViews[" + std::to_string(accessor.bufferView) +
             "].byteStride: " + std::to_string(m_stride) + " is smaller than one " + typeName(accessor.type) +
             " element (" + std::to_string(elementSize) + " bytes) of " + f);
    }
    if (m_count > 0) {
        const size_t maxCount = std::numeric_limits<size_t>::max() / m_stride;
        const bool overflow = m_count - 1 > maxCount || accessor.byteOffset > view.length;
        const size_t needed = overflow ? 0 : accessor.byteOffset + (m_count - 1) * m_stride + elementSize;
        if (overflow || needed > view.length) {
            fail(f + ".count: " + std::to_string(m_count) + " elements from byteOffset " +
                 std::to_string(accessor.byteOffset) + " need more than the " + std::to_string(view.length) +
                 " bytes of bufferViews[" + std::to_string(accessor.bufferView) + "]");
        }
    }
    m_data = view.data + accessor.byteOffset;
}

void AccessorReader::readSparse(const tinygltf::Model& model, const tinygltf::Accessor& accessor,
                                size_t elementSize) {
    const std::string f = field() + ".sparse";
    const auto& sparse = accessor.sparse;
    if (sparse.count < 1 || static_cast<size_t>(sparse.count) > m_count)
        fail(f + ".count: " + std::to_string(sparse.count) + " is not in 1.." + std::to_string(m_count) +
             " (the accessor's count)");
    const size_t n = static_cast<size_t>(sparse.count);
    const int indexType = sparse.indices.componentType;
    const size_t indexSize = indexType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE    ? 1
                             : indexType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ? 2
                             : indexType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT   ? 4
                                                                                   : 0;
    if (indexSize == 0)
        fail(f + ".indices.componentType: " + componentTypeName(indexType) +
             " is not allowed (UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT)");
    // Both ranges tightly packed from their byteOffset inside their bufferView.
    auto range = [&](int viewIndex, int byteOffset, size_t bytes, const std::string& what) {
        const ViewRange view = resolveView(model, m_source, viewIndex, f + "." + what + ".bufferView");
        if (byteOffset < 0 || static_cast<size_t>(byteOffset) > view.length ||
            bytes > view.length - static_cast<size_t>(byteOffset))
            fail(f + "." + what + ": " + std::to_string(n) + " entries from byteOffset " +
                 std::to_string(byteOffset) + " need more than the " + std::to_string(view.length) +
                 " bytes of bufferViews[" + std::to_string(viewIndex) + "]");
        return view.data + byteOffset;
    };
    const uint8_t* indices =
        range(sparse.indices.bufferView, sparse.indices.byteOffset, n * indexSize, "indices");
    const uint8_t* values =
        range(sparse.values.bufferView, sparse.values.byteOffset, n * elementSize, "values");
    m_sparseIndices.resize(n);
    m_sparseValues.resize(n);
    for (size_t k = 0; k < n; ++k) {
        uint32_t index = 0;
        std::memcpy(&index, indices + k * indexSize, indexSize); // little-endian, as glTF
        if (index >= m_count)
            fail(f + ".indices[" + std::to_string(k) + "]: " + std::to_string(index) +
                 " is not below the count " + std::to_string(m_count));
        if (k > 0 && index <= m_sparseIndices[k - 1])
            fail(f + ".indices[" + std::to_string(k) + "]: " + std::to_string(index) +
                 " does not increase (glTF requires strictly increasing sparse indices)");
        m_sparseIndices[k] = index;
        m_sparseValues[k] = values + k * elementSize;
    }
}

const uint8_t* AccessorReader::elementAddress(size_t i) const {
    if (!m_sparseIndices.empty()) {
        const auto it = std::lower_bound(m_sparseIndices.begin(), m_sparseIndices.end(), uint32_t(i));
        if (it != m_sparseIndices.end() && *it == i)
            return m_sparseValues[size_t(it - m_sparseIndices.begin())];
    }
    return m_data ? m_data + i * m_stride : nullptr;
}

std::string AccessorReader::field() const {
    return "accessors[" + std::to_string(m_accessorIndex) + "]";
}

void AccessorReader::fail(const std::string& what) const {
    throw SceneError(m_source + ": " + what);
}

float AccessorReader::component(size_t element, int c) const {
    const uint8_t* base = elementAddress(element);
    if (base == nullptr) {
        return 0.0f;
    }
    const uint8_t* p = base + static_cast<size_t>(c) * static_cast<size_t>(m_componentSize);
    // memcpy: glTF only promises component alignment, and strides can make it odd.
    switch (m_componentType) {
    case TINYGLTF_COMPONENT_TYPE_FLOAT: {
        float v;
        std::memcpy(&v, p, 4);
        return v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return m_normalized ? p[0] / 255.0f : static_cast<float>(p[0]);
    case TINYGLTF_COMPONENT_TYPE_BYTE: {
        const auto v = static_cast<int8_t>(p[0]);
        return m_normalized ? std::max(v / 127.0f, -1.0f) : static_cast<float>(v);
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
        uint16_t v;
        std::memcpy(&v, p, 2);
        return m_normalized ? v / 65535.0f : static_cast<float>(v);
    }
    case TINYGLTF_COMPONENT_TYPE_SHORT: {
        int16_t v;
        std::memcpy(&v, p, 2);
        return m_normalized ? std::max(v / 32767.0f, -1.0f) : static_cast<float>(v);
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
        uint32_t v;
        std::memcpy(&v, p, 4);
        return static_cast<float>(v);
    }
    default:
        return 0.0f;
    }
}

uint32_t AccessorReader::index(size_t i) const {
    const uint8_t* p = elementAddress(i);
    if (p == nullptr) {
        return 0;
    }
    switch (m_componentType) {
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return p[0];
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
        uint16_t v;
        std::memcpy(&v, p, 2);
        return v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
        uint32_t v;
        std::memcpy(&v, p, 4);
        return v;
    }
    default:
        return 0;
    }
}

std::vector<uint32_t> readIndices(const tinygltf::Model& model, const std::string& source,
                                  const tinygltf::Primitive& primitive, const std::string& context,
                                  size_t vertexCount, int positionAccessor) {
    std::vector<uint32_t> indices;
    if (primitive.indices < 0) {
        indices.resize(vertexCount);
        for (size_t i = 0; i < vertexCount; ++i) {
            indices[i] = static_cast<uint32_t>(i);
        }
        return indices;
    }
    AccessorExpect expect;
    expect.type = TINYGLTF_TYPE_SCALAR;
    expect.allowFloat = false;
    expect.allowPlainInts = true;
    expect.allowUnsignedInt = true;
    const AccessorReader reader(model, source, primitive.indices, expect, context + ".indices");
    const tinygltf::Accessor& accessor = model.accessors[static_cast<size_t>(primitive.indices)];
    if (accessor.componentType == TINYGLTF_COMPONENT_TYPE_BYTE ||
        accessor.componentType == TINYGLTF_COMPONENT_TYPE_SHORT) {
        throw SceneError(source + ": " + reader.field() + ".componentType: indices must be unsigned");
    }
    indices.resize(reader.count());
    for (size_t i = 0; i < reader.count(); ++i) {
        const uint32_t v = reader.index(i);
        if (v >= vertexCount) {
            throw SceneError(source + ": " + reader.field() + ".count: " + std::to_string(reader.count()) +
                             " indices reference vertex " + std::to_string(v) +
                             " but the POSITION accessor (accessors[" + std::to_string(positionAccessor) +
                             "]) has " + std::to_string(vertexCount) + " vertices");
        }
        indices[i] = v;
    }
    return indices;
}

std::vector<uint8_t> bufferViewBytes(const tinygltf::Model& model, const std::string& source,
                                     int bufferViewIndex, const std::string& context) {
    const ViewRange view = resolveView(model, source, bufferViewIndex, context);
    return {view.data, view.data + view.length};
}

} // namespace eng::scene
