// Structural checks on a parsed glTF model, run before anything reads data: every index points
// at something that exists, every byte range lies inside its buffer, and the node graph is a
// forest. tinygltf parses but does not check these, and reading unchecked indices would crash.
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "scene/gltf_internal.h"

namespace vct::gltf {
namespace {

std::string item(const char* kind, size_t i) { return std::string(kind) + " " + std::to_string(i); }

void check_ref(const Context& ctx, int ref, size_t count, const std::string& owner, const char* what,
               bool optional) {
  if (ref == -1 && optional) return;
  if (ref < 0 || static_cast<size_t>(ref) >= count) {
    fail(ctx, owner + " refers to " + what + " " + std::to_string(ref) + ", but the file has " +
                  std::to_string(count) + " " + what + (count == 1 ? "" : "s"));
  }
}

void check_buffer_views(const Context& ctx) {
  const auto& m = ctx.model;
  for (size_t i = 0; i < m.bufferViews.size(); ++i) {
    const auto& v = m.bufferViews[i];
    const std::string owner = item("bufferView", i);
    check_ref(ctx, v.buffer, m.buffers.size(), owner, "buffer", false);
    const uint64_t have = m.buffers[static_cast<size_t>(v.buffer)].data.size();
    const uint64_t end = uint64_t(v.byteOffset) + uint64_t(v.byteLength);
    if (v.byteLength == 0) fail(ctx, owner + " has byteLength 0");
    if (v.byteOffset > have || v.byteLength > have - v.byteOffset) {  // (no overflow on huge values)
      fail(ctx, owner + " covers bytes " + std::to_string(v.byteOffset) + ".." + std::to_string(end) +
                    " of buffer " + std::to_string(v.buffer) + ", which has only " + std::to_string(have) +
                    " bytes (missing or short buffer)");
    }
  }
}

// glTF 2.0 §3.6.2.3: `count` substitutions, indices (unsigned, strictly increasing, each < the
// accessor's count) and values tightly packed in their own buffer views. The index order is checked
// here too, so read_floats can apply the substitutions without re-checking.
void check_sparse(const Context& ctx, const tinygltf::Accessor& a, const std::string& owner, uint64_t elem) {
  const auto& m = ctx.model;
  const auto& sp = a.sparse;
  const std::string what = owner + " sparse";
  if (sp.count <= 0 || uint64_t(sp.count) > a.count) {
    fail(ctx, what + " count " + std::to_string(sp.count) + " must be 1.." + std::to_string(a.count));
  }
  const int index_size = tinygltf::GetComponentSizeInBytes(static_cast<uint32_t>(sp.indices.componentType));
  const bool index_type_ok = sp.indices.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                             sp.indices.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ||
                             sp.indices.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
  if (!index_type_ok) fail(ctx, what + " indices must be UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT");
  const auto fits = [&](int view, int offset, uint64_t bytes, const char* part) {
    check_ref(ctx, view, m.bufferViews.size(), what + " " + part, "bufferView", false);
    const uint64_t len = m.bufferViews[static_cast<size_t>(view)].byteLength;
    if (offset < 0 || uint64_t(offset) > len || bytes > len - uint64_t(offset)) {
      fail(ctx, what + " " + part + " need " + std::to_string(bytes) + " bytes at offset " + std::to_string(offset) +
                    " of bufferView " + std::to_string(view) + ", which has " + std::to_string(len));
    }
  };
  fits(sp.indices.bufferView, sp.indices.byteOffset, uint64_t(sp.count) * uint64_t(index_size), "indices");
  fits(sp.values.bufferView, sp.values.byteOffset, uint64_t(sp.count) * elem, "values");
  const std::vector<uint32_t> indices = read_sparse_indices(ctx, a);
  for (size_t k = 0; k < indices.size(); ++k) {
    if (indices[k] >= a.count || (k > 0 && indices[k] <= indices[k - 1])) {
      fail(ctx, what + " index " + std::to_string(k) + " (" + std::to_string(indices[k]) +
                    ") is out of range or not strictly increasing");
    }
  }
}

void check_accessors(const Context& ctx) {
  const auto& m = ctx.model;
  for (size_t i = 0; i < m.accessors.size(); ++i) {
    const auto& a = m.accessors[i];
    const std::string owner = item("accessor", i);
    const int comp_size = tinygltf::GetComponentSizeInBytes(static_cast<uint32_t>(a.componentType));
    const int comps = tinygltf::GetNumComponentsInType(static_cast<uint32_t>(a.type));
    if (comp_size <= 0 || comps <= 0) fail(ctx, owner + " has an invalid componentType or type");
    if (a.count == 0) fail(ctx, owner + " has count 0");
    if (a.sparse.isSparse) check_sparse(ctx, a, owner, uint64_t(comp_size) * uint64_t(comps));
    if (a.bufferView == -1) {  // all zeros, as glTF defines; but no allocation bomb
      if (a.count > (1u << 24)) fail(ctx, owner + " has no bufferView and an implausible count " + std::to_string(a.count));
      continue;
    }
    check_ref(ctx, a.bufferView, m.bufferViews.size(), owner, "bufferView", false);
    const auto& view = m.bufferViews[static_cast<size_t>(a.bufferView)];
    const uint64_t elem = uint64_t(comp_size) * uint64_t(comps);
    const int stride = a.ByteStride(view);
    if (stride <= 0 || (view.byteStride != 0 && view.byteStride < elem)) {
      fail(ctx, owner + " has a byteStride that does not fit its element size");
    }
    // Checked in steps so huge counts or offsets cannot overflow the arithmetic.
    const uint64_t len = view.byteLength;
    const bool fits = a.byteOffset <= len && a.count <= len && uint64_t(stride) * (uint64_t(a.count) - 1) <= len &&
                      uint64_t(a.byteOffset) + uint64_t(stride) * (uint64_t(a.count) - 1) + elem <= len;
    if (!fits) {
      const double end = double(a.byteOffset) + double(stride) * (double(a.count) - 1.0) + double(elem);
      fail(ctx, owner + " needs " + std::to_string(uint64_t(std::min(end, 1.8e19))) + " bytes of bufferView " + std::to_string(a.bufferView) +
                    ", which has " + std::to_string(view.byteLength) + " (accessor out of range)");
    }
  }
}

void check_textures(const Context& ctx) {
  const auto& m = ctx.model;
  for (size_t i = 0; i < m.images.size(); ++i) {
    const auto& img = m.images[i];
    if (img.bufferView != -1) check_ref(ctx, img.bufferView, m.bufferViews.size(), item("image", i), "bufferView", false);
  }
  for (size_t i = 0; i < m.textures.size(); ++i) {
    const auto& t = m.textures[i];
    if (t.source == -1) fail(ctx, item("texture", i) + " has no image source");
    check_ref(ctx, t.source, m.images.size(), item("texture", i), "image", false);
    check_ref(ctx, t.sampler, m.samplers.size(), item("texture", i), "sampler", true);
  }
  for (size_t i = 0; i < m.materials.size(); ++i) {
    const auto& mat = m.materials[i];
    const std::string owner = item("material", i) + " '" + mat.name + "'";
    const int refs[] = {mat.pbrMetallicRoughness.baseColorTexture.index,
                        mat.pbrMetallicRoughness.metallicRoughnessTexture.index, mat.normalTexture.index,
                        mat.occlusionTexture.index, mat.emissiveTexture.index};
    for (int r : refs) check_ref(ctx, r, m.textures.size(), owner, "texture", true);
  }
}

void check_meshes(const Context& ctx) {
  const auto& m = ctx.model;
  for (size_t i = 0; i < m.meshes.size(); ++i) {
    for (size_t p = 0; p < m.meshes[i].primitives.size(); ++p) {
      const auto& prim = m.meshes[i].primitives[p];
      const std::string owner = item("mesh", i) + " primitive " + std::to_string(p);
      for (const auto& [name, acc] : prim.attributes) {
        check_ref(ctx, acc, m.accessors.size(), owner + " attribute " + name, "accessor", false);
      }
      check_ref(ctx, prim.indices, m.accessors.size(), owner + " indices", "accessor", true);
      for (size_t t = 0; t < prim.targets.size(); ++t) {
        for (const auto& [name, acc] : prim.targets[t]) {
          check_ref(ctx, acc, m.accessors.size(), owner + " morph target " + std::to_string(t) + " " + name,
                    "accessor", false);
        }
      }
      check_ref(ctx, prim.material, m.materials.size(), owner, "material", true);
    }
  }
}

int node_light(const tinygltf::Node& n) {
  auto it = n.extensions.find("KHR_lights_punctual");
  if (it == n.extensions.end() || !it->second.Has("light")) return -1;
  const auto& v = it->second.Get("light");
  return v.IsInt() ? v.Get<int>() : -2;
}

// With one parent per node, a cycle is a parent chain that never reaches a root. Each chain is
// walked until it meets a root or a node already known to reach one, then all of it is marked:
// every node is walked once, so a chain of 10^6 nodes takes linear time (issue 38).
void check_no_cycle(const Context& ctx, const std::vector<int>& parent) {
  enum : uint8_t { kUnknown, kOnWalk, kReachesRoot };
  std::vector<uint8_t> state(parent.size(), kUnknown);
  std::vector<size_t> walk;
  for (size_t i = 0; i < parent.size(); ++i) {
    walk.clear();
    for (int p = int(i); p != -1 && state[size_t(p)] != kReachesRoot; p = parent[size_t(p)]) {
      if (state[size_t(p)] == kOnWalk) fail(ctx, "node graph has a cycle through " + item("node", size_t(p)));
      state[size_t(p)] = kOnWalk;
      walk.push_back(size_t(p));
    }
    for (size_t w : walk) state[w] = kReachesRoot;
  }
}

void check_nodes(const Context& ctx) {
  const auto& m = ctx.model;
  std::vector<int> parent(m.nodes.size(), -1);
  for (size_t i = 0; i < m.nodes.size(); ++i) {
    const auto& n = m.nodes[i];
    const std::string owner = item("node", i) + (n.name.empty() ? "" : " '" + n.name + "'");
    check_ref(ctx, n.mesh, m.meshes.size(), owner, "mesh", true);
    check_ref(ctx, n.camera, m.cameras.size(), owner, "camera", true);
    check_ref(ctx, n.skin, m.skins.size(), owner, "skin", true);
    check_ref(ctx, node_light(n), m.lights.size(), owner, "light", true);
    for (int c : n.children) {
      check_ref(ctx, c, m.nodes.size(), owner + " (children)", "node", false);
      if (static_cast<size_t>(c) == i) fail(ctx, owner + " is its own child (node graph has a cycle)");
      if (parent[static_cast<size_t>(c)] != -1) {
        fail(ctx, item("node", static_cast<size_t>(c)) + " has two parents (nodes " +
                      std::to_string(parent[static_cast<size_t>(c)]) + " and " + std::to_string(i) +
                      "); glTF node graphs must be trees");
      }
      parent[static_cast<size_t>(c)] = static_cast<int>(i);
    }
  }
  check_no_cycle(ctx, parent);
  for (size_t s = 0; s < m.scenes.size(); ++s) {
    for (int root : m.scenes[s].nodes) {
      check_ref(ctx, root, m.nodes.size(), item("scene", s), "node", false);
      if (parent[static_cast<size_t>(root)] != -1) {
        fail(ctx, item("scene", s) + " lists node " + std::to_string(root) + " as a root, but it is a child of node " +
                      std::to_string(parent[static_cast<size_t>(root)]));
      }
    }
  }
  if (!m.scenes.empty()) check_ref(ctx, m.defaultScene, m.scenes.size(), "the file's 'scene'", "scene", true);
}

void check_required_extensions(const Context& ctx) {
  const auto& ok = supported_extensions();
  for (const auto& e : ctx.model.extensionsRequired) {
    if (std::find(ok.begin(), ok.end(), e) == ok.end()) {
      fail(ctx, "requires extension " + e + ", which is not supported (docs/scenes.md lists the supported ones)");
    }
  }
}

}  // namespace

void validate_model(const Context& ctx) {
  check_required_extensions(ctx);
  check_buffer_views(ctx);
  check_accessors(ctx);
  check_textures(ctx);
  check_meshes(ctx);
  check_nodes(ctx);
}

}  // namespace vct::gltf
