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
  if (!v.base) return out;
  for (size_t i = 0; i < a.count; ++i) {
    for (int c = 0; c < components; ++c) {
      const float f = component(v.base + i * v.stride + size_t(c * v.comp_size), a.componentType, a.normalized);
      if (!std::isfinite(f)) {
        fail(ctx, what + " (accessor " + std::to_string(index) + ") element " + std::to_string(i) +
                      " is not a finite number (NaN or Inf)");
      }
      out[i * size_t(components) + size_t(c)] = f;
    }
  }
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
  if (!v.base) return out;
  for (size_t i = 0; i < a.count; ++i) {
    const unsigned char* p = v.base + i * v.stride;
    uint32_t x = 0;
    if (v.comp_size == 1) {
      x = *p;
    } else if (v.comp_size == 2) {
      uint16_t s;
      std::memcpy(&s, p, 2);
      x = s;
    } else {
      std::memcpy(&x, p, 4);
    }
    out[i] = x;
  }
  return out;
}

}  // namespace vct::gltf
