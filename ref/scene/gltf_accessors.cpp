// Typed reads of glTF accessors. Ranges were checked by validate_model; these functions only
// convert component types (glTF 2.0 §3.11 normalization rules) and refuse non-finite values.
#include <algorithm>
#include <cmath>
#include <cstring>

#include "scene/gltf_internal.h"

namespace vct::gltf {
namespace {

// One component at `p` as float, normalized integers mapped as glTF specifies.
float component(const unsigned char* p, int type, bool normalized) {
  switch (type) {
    case TINYGLTF_COMPONENT_TYPE_FLOAT: {
      float f;
      std::memcpy(&f, p, 4);
      return f;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return normalized ? float(*p) / 255.0f : float(*p);
    case TINYGLTF_COMPONENT_TYPE_BYTE: {
      const float v = float(static_cast<int8_t>(*p));
      return normalized ? std::max(v / 127.0f, -1.0f) : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
      uint16_t u;
      std::memcpy(&u, p, 2);
      return normalized ? float(u) / 65535.0f : float(u);
    }
    case TINYGLTF_COMPONENT_TYPE_SHORT: {
      int16_t s;
      std::memcpy(&s, p, 2);
      return normalized ? std::max(float(s) / 32767.0f, -1.0f) : float(s);
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
      uint32_t u;
      std::memcpy(&u, p, 4);
      return float(u);
    }
    default: return 0.0f;
  }
}

struct View {
  const unsigned char* base = nullptr;  // null: accessor without bufferView (all zeros)
  size_t stride = 0;
  int comp_size = 0;
  int comps = 0;
};

View view_of(const Context& ctx, const tinygltf::Accessor& a) {
  View v;
  v.comp_size = tinygltf::GetComponentSizeInBytes(static_cast<uint32_t>(a.componentType));
  v.comps = tinygltf::GetNumComponentsInType(static_cast<uint32_t>(a.type));
  if (a.bufferView < 0) return v;
  const auto& bv = ctx.model.bufferViews[static_cast<size_t>(a.bufferView)];
  v.base = ctx.model.buffers[static_cast<size_t>(bv.buffer)].data.data() + bv.byteOffset + a.byteOffset;
  v.stride = static_cast<size_t>(a.ByteStride(bv));
  return v;
}

uint32_t unsigned_at(const unsigned char* p, int size) {
  if (size == 1) return *p;
  if (size == 2) {
    uint16_t s;
    std::memcpy(&s, p, 2);
    return s;
  }
  uint32_t x;
  std::memcpy(&x, p, 4);
  return x;
}

const unsigned char* view_bytes(const Context& ctx, int view, int offset) {
  const auto& bv = ctx.model.bufferViews[static_cast<size_t>(view)];
  return ctx.model.buffers[static_cast<size_t>(bv.buffer)].data.data() + bv.byteOffset + size_t(offset);
}

}  // namespace

std::vector<uint32_t> read_sparse_indices(const Context& ctx, const tinygltf::Accessor& a) {
  const auto& idx = a.sparse.indices;
  const int size = tinygltf::GetComponentSizeInBytes(static_cast<uint32_t>(idx.componentType));
  const unsigned char* p = view_bytes(ctx, idx.bufferView, idx.byteOffset);
  std::vector<uint32_t> out(size_t(a.sparse.count));
  for (size_t k = 0; k < out.size(); ++k) out[k] = unsigned_at(p + k * size_t(size), size);
  return out;
}

namespace {

// glTF 2.0 §3.6.2.3: element indices[k] of the dense (or all-zero) data is replaced by values[k];
// the values are tightly packed elements of the accessor's own type. Ranges and the index order were
// checked by validate_model.
template <typename T, typename Convert>
void apply_sparse(const Context& ctx, const tinygltf::Accessor& a, int comps, int comp_size, std::vector<T>& out,
                  Convert convert) {
  if (!a.sparse.isSparse) return;
  const std::vector<uint32_t> indices = read_sparse_indices(ctx, a);
  const unsigned char* values = view_bytes(ctx, a.sparse.values.bufferView, a.sparse.values.byteOffset);
  const size_t elem = size_t(comps) * size_t(comp_size);
  for (size_t k = 0; k < indices.size(); ++k) {
    for (int c = 0; c < comps; ++c) {
      out[size_t(indices[k]) * size_t(comps) + size_t(c)] = convert(values + k * elem + size_t(c * comp_size), k);
    }
  }
}

}  // namespace

std::vector<float> read_floats(const Context& ctx, int index, int components, const std::string& what) {
  const auto& a = ctx.model.accessors[static_cast<size_t>(index)];
  const View v = view_of(ctx, a);
  if (v.comps != components) {
    fail(ctx, what + " (accessor " + std::to_string(index) + ") has " + std::to_string(v.comps) +
                  " components per element, expected " + std::to_string(components));
  }
  if (a.componentType == TINYGLTF_COMPONENT_TYPE_DOUBLE) fail(ctx, what + ": double components are not glTF 2.0");
  std::vector<float> out(a.count * size_t(components), 0.0f);
  const auto finite = [&](const unsigned char* p, size_t element) {
    const float f = component(p, a.componentType, a.normalized);
    if (!std::isfinite(f)) {
      fail(ctx, what + " (accessor " + std::to_string(index) + ") element " + std::to_string(element) +
                    " is not a finite number (NaN or Inf)");
    }
    return f;
  };
  if (v.base) {
    for (size_t i = 0; i < a.count; ++i) {
      for (int c = 0; c < components; ++c) {
        out[i * size_t(components) + size_t(c)] = finite(v.base + i * v.stride + size_t(c * v.comp_size), i);
      }
    }
  }
  apply_sparse(ctx, a, components, v.comp_size, out, finite);
  return out;
}

std::vector<uint32_t> read_indices(const Context& ctx, int index, const std::string& what) {
  const auto& a = ctx.model.accessors[static_cast<size_t>(index)];
  const View v = view_of(ctx, a);
  const bool ok_type = a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                       a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ||
                       a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
  if (v.comps != 1 || !ok_type) fail(ctx, what + " (accessor " + std::to_string(index) + ") must be unsigned integer SCALAR");
  std::vector<uint32_t> out(a.count, 0u);
  if (v.base) {
    for (size_t i = 0; i < a.count; ++i) out[i] = unsigned_at(v.base + i * v.stride, v.comp_size);
  }
  apply_sparse(ctx, a, 1, v.comp_size, out, [&](const unsigned char* p, size_t) { return unsigned_at(p, v.comp_size); });
  return out;
}

}  // namespace vct::gltf
