// Checked accessor reads: a malformed file (an index past an array, a view past its buffer, a
// component type the attribute does not allow) is a user-input error, never an out-of-bounds read.
#include "scene/gltf_accessors.h"

#include "core/input_error.h"
#include "core/strings.h"

#include <cmath>
#include <cstring>
#include <limits>

namespace ispm {

void GltfFile::fail(const std::string& jsonPath, const std::string& what) const {
    throwInputError(path, jsonPath, what);
}

namespace {

int getComponentBytes(int componentType) {
    switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
        return 2;
    case TINYGLTF_COMPONENT_TYPE_INT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
        return 4;
    default:
        return 0;
    }
}

// The accessor's elements as byte pointers into its buffer, after checking that accessor, view
// and buffer exist and that every element lies inside the view and the buffer.
struct AccessorView {
    const unsigned char* first = nullptr;
    size_t stride = 0;
    size_t count = 0;
    int componentType = 0;
};

AccessorView viewAccessor(const GltfFile& file, int index, int type, const std::string& usePath,
                          const char* what) {
    const tinygltf::Model& model = file.model;
    if (index < 0 || static_cast<size_t>(index) >= model.accessors.size()) {
        file.fail(usePath,
                  strCat("an accessor index below ", model.accessors.size(), ", got ", index));
    }
    const std::string at = strCat("/accessors/", index);
    const tinygltf::Accessor& accessor = model.accessors[static_cast<size_t>(index)];
    if (accessor.type != type) file.fail(at + "/type", strCat(what, " (used at ", usePath, ")"));
    if (accessor.sparse.isSparse) file.fail(at + "/sparse", "an accessor without sparse storage");
    const int componentBytes = getComponentBytes(accessor.componentType);
    if (componentBytes == 0) file.fail(at + "/componentType", "a glTF component type");
    const auto viewIndex = static_cast<size_t>(accessor.bufferView);
    if (accessor.bufferView < 0 || viewIndex >= model.bufferViews.size()) {
        file.fail(at + "/bufferView", "a buffer view index (accessors without data are not read)");
    }
    const tinygltf::BufferView& view = model.bufferViews[viewIndex];
    const std::string viewAt = strCat("/bufferViews/", viewIndex);
    const auto bufferIndex = static_cast<size_t>(view.buffer);
    if (view.buffer < 0 || bufferIndex >= model.buffers.size()) {
        file.fail(viewAt + "/buffer", "a buffer index");
    }
    const size_t bufferBytes = model.buffers[bufferIndex].data.size();
    const size_t elementBytes =
        static_cast<size_t>(componentBytes) *
        static_cast<size_t>(tinygltf::GetNumComponentsInType(static_cast<uint32_t>(type)));
    const size_t stride = view.byteStride == 0 ? elementBytes : view.byteStride;
    if (stride < elementBytes) file.fail(viewAt + "/byteStride", "a stride of at least an element");
    if (view.byteOffset > bufferBytes || view.byteLength > bufferBytes - view.byteOffset) {
        file.fail(viewAt, strCat("a view inside its buffer (", bufferBytes, " bytes)"));
    }
    if (accessor.count == 0) file.fail(at + "/count", "at least one element");
    // Overflow-safe: count and stride are bounded by the view's length before they multiply.
    const size_t last = accessor.count - 1;
    if (accessor.byteOffset > view.byteLength || last > view.byteLength / stride ||
        accessor.byteOffset + last * stride + elementBytes > view.byteLength) {
        file.fail(at, strCat("elements inside buffer view ", viewIndex, " (", view.byteLength,
                             " bytes)"));
    }
    AccessorView v;
    v.first = model.buffers[bufferIndex].data.data() + view.byteOffset + accessor.byteOffset;
    v.stride = stride;
    v.count = accessor.count;
    v.componentType = accessor.componentType;
    return v;
}

template <typename T> T readComponent(const unsigned char* at) {
    T value;
    std::memcpy(&value, at, sizeof(T));
    return value;
}

// One component as a float: floats as they are, unsigned normalised integers divided by their
// maximum (glTF's texture coordinates may be stored so).
float readFloatComponent(const AccessorView& v, const unsigned char* at) {
    switch (v.componentType) {
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return float(at[0]) / float(std::numeric_limits<uint8_t>::max());
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
        return float(readComponent<uint16_t>(at)) / float(std::numeric_limits<uint16_t>::max());
    default:
        return readComponent<float>(at);
    }
}

template <int N>
std::vector<glm::vec<N, float>> readFloatVectors(const GltfFile& file, const AccessorView& v,
                                                 int index) {
    std::vector<glm::vec<N, float>> out(v.count);
    const size_t componentBytes = static_cast<size_t>(getComponentBytes(v.componentType));
    for (size_t i = 0; i < v.count; ++i) {
        for (int c = 0; c < N; ++c) {
            const float x = readFloatComponent(v, v.first + i * v.stride +
                                                      static_cast<size_t>(c) * componentBytes);
            if (!std::isfinite(x)) {
                file.fail(strCat("/accessors/", index),
                          strCat("finite numbers, element ", i, " is not"));
            }
            out[i][c] = x;
        }
    }
    return out;
}

} // namespace

std::vector<glm::vec3> readPositions(const GltfFile& file, int accessor,
                                     const std::string& usePath) {
    const AccessorView v =
        viewAccessor(file, accessor, TINYGLTF_TYPE_VEC3, usePath, "VEC3 positions");
    if (v.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT) {
        file.fail(strCat("/accessors/", accessor, "/componentType"), "5126 (float positions)");
    }
    return readFloatVectors<3>(file, v, accessor);
}

std::vector<glm::vec3> readNormals(const GltfFile& file, int accessor, const std::string& usePath) {
    const AccessorView v =
        viewAccessor(file, accessor, TINYGLTF_TYPE_VEC3, usePath, "VEC3 normals");
    if (v.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT) {
        file.fail(strCat("/accessors/", accessor, "/componentType"), "5126 (float normals)");
    }
    std::vector<glm::vec3> normals = readFloatVectors<3>(file, v, accessor);
    for (size_t i = 0; i < normals.size(); ++i) {
        // The spec asks for unit normals; exporters round them, so any length but zero will do.
        const float length = glm::length(normals[i]);
        if (!(length > 0.0f && std::isfinite(length))) {
            file.fail(strCat("/accessors/", accessor),
                      strCat("normals of non-zero length, element ", i, " is (", normals[i].x, ", ",
                             normals[i].y, ", ", normals[i].z, ")"));
        }
        normals[i] /= length;
    }
    return normals;
}

std::vector<glm::vec4> readTangents(const GltfFile& file, int accessor,
                                    const std::string& usePath) {
    const AccessorView v =
        viewAccessor(file, accessor, TINYGLTF_TYPE_VEC4, usePath, "VEC4 tangents");
    if (v.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT) {
        file.fail(strCat("/accessors/", accessor, "/componentType"), "5126 (float tangents)");
    }
    std::vector<glm::vec4> tangents = readFloatVectors<4>(file, v, accessor);
    for (size_t i = 0; i < tangents.size(); ++i) {
        // As normals: any length but zero; w is the handedness, +-1 (its sign is kept).
        const float length = glm::length(glm::vec3(tangents[i]));
        if (!(length > 0.0f && std::isfinite(length)) || tangents[i].w == 0.0f) {
            file.fail(strCat("/accessors/", accessor),
                      strCat("tangents of non-zero length with w = +-1, element ", i, " is (",
                             tangents[i].x, ", ", tangents[i].y, ", ", tangents[i].z, ", ",
                             tangents[i].w, ")"));
        }
        tangents[i] =
            glm::vec4(glm::vec3(tangents[i]) / length, tangents[i].w < 0.0f ? -1.0f : 1.0f);
    }
    return tangents;
}

std::vector<glm::vec2> readTexcoords(const GltfFile& file, int accessor,
                                     const std::string& usePath) {
    const AccessorView v =
        viewAccessor(file, accessor, TINYGLTF_TYPE_VEC2, usePath, "VEC2 texture coordinates");
    if (v.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT &&
        v.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
        v.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT) {
        file.fail(strCat("/accessors/", accessor, "/componentType"),
                  "5126, 5121 or 5123 (float or normalised unsigned texture coordinates)");
    }
    return readFloatVectors<2>(file, v, accessor);
}

std::vector<uint32_t> readIndices(const GltfFile& file, int accessor, size_t vertexCount,
                                  const std::string& usePath) {
    const AccessorView v =
        viewAccessor(file, accessor, TINYGLTF_TYPE_SCALAR, usePath, "SCALAR indices");
    std::vector<uint32_t> out(v.count);
    for (size_t i = 0; i < v.count; ++i) {
        const unsigned char* at = v.first + i * v.stride;
        switch (v.componentType) {
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
            out[i] = at[0];
            break;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
            out[i] = readComponent<uint16_t>(at);
            break;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
            out[i] = readComponent<uint32_t>(at);
            break;
        default:
            file.fail(strCat("/accessors/", accessor, "/componentType"),
                      "5121, 5123 or 5125 (unsigned indices)");
        }
        if (out[i] >= vertexCount) {
            file.fail(strCat("/accessors/", accessor),
                      strCat("indices below the vertex count ", vertexCount, ", element ", i,
                             " is ", out[i]));
        }
    }
    return out;
}

} // namespace ispm
