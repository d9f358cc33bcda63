// Walks the node forest of the default scene, flattening every mesh primitive into world-space
// triangles (TRS or matrix transforms; normals by the inverse transpose; winding flipped under
// mirroring transforms) and collecting the camera, lights (all three KHR_lights_punctual kinds) and particle emitters.
#include <algorithm>
#include <cmath>

#include "scene/gltf_internal.h"
#include "scene/tangents.h"

namespace vct::gltf {
namespace {

mat4 local_matrix(const Context& ctx, const tinygltf::Node& n, int index) {
  mat4 m(1.0f);
  if (n.matrix.size() == 16) {
    for (int i = 0; i < 16; ++i) m[i / 4][i % 4] = float(n.matrix[size_t(i)]);  // column-major, as glTF
  } else {
    mat4 t(1.0f), r(1.0f), s(1.0f);
    if (n.translation.size() == 3) t = glm::translate(mat4(1.0f), vec3(float(n.translation[0]), float(n.translation[1]), float(n.translation[2])));
    if (n.rotation.size() == 4) {
      // glTF stores (x, y, z, w); glm::quat's constructor takes w first.
      const quat q(float(n.rotation[3]), float(n.rotation[0]), float(n.rotation[1]), float(n.rotation[2]));
      const float len = glm::length(q);
      if (!(len > 0.0f)) fail(ctx, "node " + std::to_string(index) + " has a zero rotation quaternion");
      r = glm::mat4_cast(q / len);
    }
    if (n.scale.size() == 3) s = glm::scale(mat4(1.0f), vec3(float(n.scale[0]), float(n.scale[1]), float(n.scale[2])));
    m = t * r * s;
  }
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) {
      if (!std::isfinite(m[c][r])) fail(ctx, "node " + std::to_string(index) + " has a non-finite transform");
    }
  }
  return m;
}

// Triangle corner indices from a primitive's mode; false for points and lines.
bool triangulate(const std::vector<uint32_t>& idx, int mode, std::vector<uvec3>& out) {
  if (mode == -1 || mode == TINYGLTF_MODE_TRIANGLES) {
    for (size_t i = 0; i + 2 < idx.size(); i += 3) out.emplace_back(idx[i], idx[i + 1], idx[i + 2]);
  } else if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
    for (size_t i = 0; i + 2 < idx.size(); ++i) {
      // Every other triangle swaps its first two corners to keep a consistent winding.
      if (i % 2 == 0) out.emplace_back(idx[i], idx[i + 1], idx[i + 2]);
      else out.emplace_back(idx[i + 1], idx[i], idx[i + 2]);
    }
  } else if (mode == TINYGLTF_MODE_TRIANGLE_FAN) {
    for (size_t i = 1; i + 1 < idx.size(); ++i) out.emplace_back(idx[0], idx[i], idx[i + 1]);
  } else {
    return false;
  }
  return true;
}

// A triangle with repeated corners or (relative to its longest edge) no area has no normal.
bool degenerate(const vec3& a, const vec3& b, const vec3& c) {
  const glm::dvec3 e1 = glm::dvec3(b) - glm::dvec3(a), e2 = glm::dvec3(c) - glm::dvec3(a), e3 = glm::dvec3(c) - glm::dvec3(b);
  const double area2 = glm::length(glm::cross(e1, e2));
  const double longest = std::max({glm::dot(e1, e1), glm::dot(e2, e2), glm::dot(e3, e3)});
  return !(area2 > 1e-7 * longest) || longest == 0.0;
}

// glTF 2.0 §3.7.2.1 allows COLOR_0 and TEXCOORD_n as float or as normalized unsigned byte/short
// only: a uint32 colour (up to 4e9) would multiply the base colour unbounded.
void check_color_or_uv_type(const Context& ctx, const tinygltf::Accessor& a, const std::string& what) {
  const bool ok = a.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT ||
                  (a.normalized && (a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                                    a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT));
  if (!ok) fail(ctx, what + " must be FLOAT or normalized UNSIGNED_BYTE/UNSIGNED_SHORT (glTF 2.0 3.7.2.1)");
}

std::vector<vec2> read_uv(const Context& ctx, const tinygltf::Primitive& p, const char* name, size_t count,
                          const std::vector<float>& weights, const std::string& owner) {
  auto it = p.attributes.find(name);
  if (it == p.attributes.end()) return {};
  check_color_or_uv_type(ctx, ctx.model.accessors[size_t(it->second)],
                         owner + " " + name + " (accessor " + std::to_string(it->second) + ")");
  std::vector<float> f = read_floats(ctx, it->second, 2, owner + " " + name);
  if (f.size() != count * 2) fail(ctx, owner + " " + name + " count differs from POSITION count");
  add_morph_displacements(ctx, p, weights, name, 2, f, owner);
  std::vector<vec2> out(count);
  for (size_t i = 0; i < count; ++i) out[i] = vec2(f[2 * i], f[2 * i + 1]);
  return out;
}

// One primitive's vertices after transformation, before it is appended to the scene.
struct Mesh {
  std::vector<vec3> pos, nrm;
  std::vector<vec4> tan;
  std::vector<vec2> uv0, uv1;
  std::vector<vec4> col;  // COLOR_0, linear RGBA; empty = white
  std::vector<uvec3> tris;
};

// COLOR_0 (glTF 2.0 §3.7.2.1): VEC3 or VEC4, float or normalized unsigned byte/short, linear; it
// multiplies the base colour (alpha included). Morph targets displace it like any attribute.
std::vector<vec4> read_color(const Context& ctx, const tinygltf::Primitive& p, size_t count,
                             const std::vector<float>& weights, const std::string& owner) {
  auto it = p.attributes.find("COLOR_0");
  if (it == p.attributes.end()) return {};
  const auto& a = ctx.model.accessors[size_t(it->second)];
  const int comps = a.type == TINYGLTF_TYPE_VEC4 ? 4 : 3;
  check_color_or_uv_type(ctx, a, owner + " COLOR_0 (accessor " + std::to_string(it->second) + ")");
  std::vector<float> f = read_floats(ctx, it->second, comps, owner + " COLOR_0");
  if (f.size() != count * size_t(comps)) fail(ctx, owner + " COLOR_0 count differs from POSITION count");
  add_morph_displacements(ctx, p, weights, "COLOR_0", comps, f, owner);
  std::vector<vec4> out(count);
  for (size_t i = 0; i < count; ++i) {
    const float* c = &f[i * size_t(comps)];
    out[i] = vec4(c[0], c[1], c[2], comps == 4 ? c[3] : 1.0f);
  }
  return out;
}

// Each triangle gets its own three vertices with the face normal (glTF: flat normals when
// NORMAL is absent).
void unweld_with_flat_normals(Mesh& m) {
  Mesh f;
  for (const uvec3& t : m.tris) {
    const vec3 n = glm::normalize(glm::cross(m.pos[t.y] - m.pos[t.x], m.pos[t.z] - m.pos[t.x]));
    const uint32_t base = uint32_t(f.pos.size());
    for (uint32_t v : {t.x, t.y, t.z}) {
      f.pos.push_back(m.pos[v]);
      f.nrm.push_back(n);
      if (!m.tan.empty()) f.tan.push_back(m.tan[v]);
      if (!m.uv0.empty()) f.uv0.push_back(m.uv0[v]);
      if (!m.uv1.empty()) f.uv1.push_back(m.uv1[v]);
      if (!m.col.empty()) f.col.push_back(m.col[v]);
    }
    f.tris.emplace_back(base, base + 1, base + 2);
  }
  m = std::move(f);
}

class Flattener {
 public:
  Flattener(const Context& ctx, Scene& scene) : ctx_(ctx), scene_(scene) {}

  void run() {
    std::vector<int> roots = root_nodes();
    struct Item {
      int node;
      mat4 parent;
    };
    // Explicit stack (deep hierarchies must not overflow the call stack); pre-order, children
    // in file order, so "the first camera" is well defined.
    std::vector<Item> stack;
    for (auto it = roots.rbegin(); it != roots.rend(); ++it) stack.push_back({*it, mat4(1.0f)});
    while (!stack.empty()) {
      const Item item = stack.back();
      stack.pop_back();
      const auto& n = ctx_.model.nodes[size_t(item.node)];
      const mat4 world = item.parent * local_matrix(ctx_, n, item.node);
      check_finite(world, item.node);
      visit(item.node, world);
      for (auto c = n.children.rbegin(); c != n.children.rend(); ++c) stack.push_back({*c, world});
    }
    if (!any_uv1_) scene_.uv1.clear();
    if (!any_color_) scene_.colors.clear();
  }

 private:
  std::vector<int> root_nodes() const {
    const auto& m = ctx_.model;
    if (!m.scenes.empty()) return m.scenes[size_t(m.defaultScene >= 0 ? m.defaultScene : 0)].nodes;
    std::vector<bool> child(m.nodes.size(), false);
    for (const auto& n : m.nodes)
      for (int c : n.children) child[size_t(c)] = true;
    std::vector<int> roots;
    for (size_t i = 0; i < m.nodes.size(); ++i)
      if (!child[i]) roots.push_back(int(i));
    if (!roots.empty()) scene_.stats.warnings.push_back("the file has no scenes; rendering all root nodes");
    return roots;
  }

  void visit(int index, const mat4& world) {
    const auto& n = ctx_.model.nodes[size_t(index)];
    if (n.mesh >= 0) {
      if (n.skin >= 0) warn("node " + std::to_string(index) + ": skinning is ignored (bind pose is rendered)");
      const auto& mesh = ctx_.model.meshes[size_t(n.mesh)];
      const std::vector<float> weights = morph_weights(ctx_, index, n.mesh);
      for (size_t p = 0; p < mesh.primitives.size(); ++p) add_primitive(n.mesh, int(p), world, weights);
    }
    if (n.camera >= 0 && !camera_found_) {
      scene_.camera = make_camera(ctx_, n.camera, world);
      camera_found_ = true;
    }
    auto light = n.extensions.find("KHR_lights_punctual");
    if (light != n.extensions.end() && light->second.Has("light")) {
      scene_.lights.push_back(make_light(ctx_, light->second.Get("light").Get<int>(), world));
    }
    ParticleEmitter e;
    if (read_particles(ctx_, index, world, e)) scene_.emitters.push_back(e);
  }

  void warn(const std::string& w) { scene_.stats.warnings.push_back(w); }

  // Each local matrix is finite (local_matrix), but their product down a chain can overflow float.
  void check_finite(const mat4& world, int node) const {
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r)
        if (!std::isfinite(world[c][r]))
          fail(ctx_, "node " + std::to_string(node) + ": its world transform (the product of its ancestors') "
                     "is not finite (it overflows float)");
  }

  // A morph target's TANGENT is a VEC3 displacement of the VEC4 tangent's xyz (glTF 2.0 §3.7.2.2):
  // handedness (w) is not morphed.
  void add_tangent_displacements(const tinygltf::Primitive& prim, const std::vector<float>& weights,
                                 std::vector<float>& tf, const std::string& owner) {
    std::vector<float> xyz(tf.size() / 4 * 3);
    for (size_t i = 0; i < xyz.size() / 3; ++i)
      for (int c = 0; c < 3; ++c) xyz[3 * i + size_t(c)] = tf[4 * i + size_t(c)];
    add_morph_displacements(ctx_, prim, weights, "TANGENT", 3, xyz, owner);
    for (size_t i = 0; i < xyz.size() / 3; ++i)
      for (int c = 0; c < 3; ++c) tf[4 * i + size_t(c)] = xyz[3 * i + size_t(c)];
  }

  void add_primitive(int mesh_index, int prim_index, const mat4& world, const std::vector<float>& weights) {
    const auto& prim = ctx_.model.meshes[size_t(mesh_index)].primitives[size_t(prim_index)];
    const std::string owner = "mesh " + std::to_string(mesh_index) + " primitive " + std::to_string(prim_index);
    auto pos_it = prim.attributes.find("POSITION");
    if (pos_it == prim.attributes.end()) fail(ctx_, owner + " has no POSITION attribute");
    std::vector<float> pf = read_floats(ctx_, pos_it->second, 3, owner + " POSITION");
    add_morph_displacements(ctx_, prim, weights, "POSITION", 3, pf, owner);
    const size_t count = pf.size() / 3;

    std::vector<uint32_t> idx;
    if (prim.indices >= 0) {
      idx = read_indices(ctx_, prim.indices, owner + " indices");
      for (size_t i = 0; i < idx.size(); ++i) {
        if (idx[i] >= count) {
          fail(ctx_, owner + " index " + std::to_string(i) + " is " + std::to_string(idx[i]) + ", but there are only " +
                         std::to_string(count) + " vertices (index out of range)");
        }
      }
    } else {
      idx.resize(count);
      for (size_t i = 0; i < count; ++i) idx[i] = uint32_t(i);
    }
    Mesh m;
    if (!triangulate(idx, prim.mode, m.tris)) {
      ++scene_.stats.non_triangle_primitives_skipped;
      warn(owner + " has mode " + std::to_string(prim.mode) + " (points or lines); skipped");
      return;
    }

    // World-space attributes. Normals use the inverse transpose; mirroring flips winding and
    // tangent handedness so the frame stays right-handed with the flipped geometry.
    const mat3 linear(world);
    const float det = glm::determinant(linear);
    const mat3 normal_matrix = std::abs(det) > 1e-30f ? glm::transpose(glm::inverse(linear)) : mat3(1.0f);
    m.pos.resize(count);
    for (size_t i = 0; i < count; ++i) {
      m.pos[i] = vec3(world * vec4(pf[3 * i], pf[3 * i + 1], pf[3 * i + 2], 1.0f));
      if (!std::isfinite(m.pos[i].x) || !std::isfinite(m.pos[i].y) || !std::isfinite(m.pos[i].z))
        fail(ctx_, owner + " vertex " + std::to_string(i) + ": its world-space position is not finite (overflows float)");
    }
    bool have_normals = false;
    if (auto it = prim.attributes.find("NORMAL"); it != prim.attributes.end()) {
      std::vector<float> nf = read_floats(ctx_, it->second, 3, owner + " NORMAL");
      if (nf.size() != pf.size()) fail(ctx_, owner + " NORMAL count differs from POSITION count");
      add_morph_displacements(ctx_, prim, weights, "NORMAL", 3, nf, owner);
      m.nrm.resize(count);
      have_normals = true;
      for (size_t i = 0; i < count && have_normals; ++i) {
        const vec3 n = normal_matrix * vec3(nf[3 * i], nf[3 * i + 1], nf[3 * i + 2]);
        const float len = glm::length(n);
        if (len > 0.0f) m.nrm[i] = n / len;
        else have_normals = false;  // a zero normal: fall back to flat normals for the primitive
      }
      if (!have_normals) {
        warn(owner + " has zero-length normals; using flat normals");
        m.nrm.clear();
      }
    }
    if (auto it = prim.attributes.find("TANGENT"); it != prim.attributes.end() && have_normals) {
      std::vector<float> tf = read_floats(ctx_, it->second, 4, owner + " TANGENT");
      if (tf.size() != count * 4) fail(ctx_, owner + " TANGENT count differs from POSITION count");
      add_tangent_displacements(prim, weights, tf, owner);
      m.tan.resize(count);
      for (size_t i = 0; i < count; ++i) {
        const vec3 t = linear * vec3(tf[4 * i], tf[4 * i + 1], tf[4 * i + 2]);
        const float w = (tf[4 * i + 3] < 0.0f ? -1.0f : 1.0f) * (det < 0.0f ? -1.0f : 1.0f);
        m.tan[i] = orthogonalize_tangent(m.nrm[i], vec4(t, w));
      }
    }
    m.uv0 = read_uv(ctx_, prim, "TEXCOORD_0", count, weights, owner);
    m.uv1 = read_uv(ctx_, prim, "TEXCOORD_1", count, weights, owner);
    m.col = read_color(ctx_, prim, count, weights, owner);
    if (m.uv1.empty() && uses_uv1(prim)) warn(owner + ": its material samples TEXCOORD_1, which it lacks (reads (0, 0))");
    if (det < 0.0f) {
      for (uvec3& t : m.tris) std::swap(t.y, t.z);
    }

    // Drop degenerate triangles (counted), then fill in what the file did not provide.
    std::vector<uvec3> kept;
    kept.reserve(m.tris.size());
    for (const uvec3& t : m.tris) {
      if (t.x == t.y || t.y == t.z || t.x == t.z || degenerate(m.pos[t.x], m.pos[t.y], m.pos[t.z])) {
        ++scene_.stats.degenerate_triangles_dropped;
      } else {
        kept.push_back(t);
      }
    }
    m.tris = std::move(kept);
    if (m.tris.empty()) return;
    if (!have_normals) unweld_with_flat_normals(m);
    if (m.tan.empty()) {
      m.tan = generate_tangents(m.pos, m.nrm, tangent_uv_set(prim, m), m.tris);
      warn_generated_tangents(mesh_index, prim);
    }
    append(m, material_of(prim));
  }

  // The Khronos validator warns when a normal-mapped primitive has no TANGENT; we generate them
  // (docs/scenes.md, "Tangents": not MikkTSpace), said once per mesh.
  void warn_generated_tangents(int mesh_index, const tinygltf::Primitive& prim) {
    if (prim.material < 0 || !scene_.materials[size_t(prim.material)].normal_texture.present()) return;
    if (std::find(tangent_warned_.begin(), tangent_warned_.end(), mesh_index) != tangent_warned_.end()) return;
    tangent_warned_.push_back(mesh_index);
    const std::string& name = ctx_.model.meshes[size_t(mesh_index)].name;
    warn("mesh " + std::to_string(mesh_index) + (name.empty() ? "" : " '" + name + "'") + ": no TANGENT for material '" +
         scene_.materials[size_t(prim.material)].name +
         "' (normal-mapped); tangents generated from its UVs (not MikkTSpace: baked normal maps may differ at UV seams)");
  }

  bool uses_uv1(const tinygltf::Primitive& prim) const {
    if (prim.material < 0) return false;
    const Material& m = scene_.materials[size_t(prim.material)];
    for (const TextureRef* r : {&m.base_color_texture, &m.metallic_roughness_texture, &m.normal_texture, &m.emissive_texture}) {
      if (r->present() && r->texcoord == 1) return true;
    }
    return false;
  }

  // Tangents follow the UV set the normal map samples (TEXCOORD_0 unless it says otherwise).
  const std::vector<vec2>& tangent_uv_set(const tinygltf::Primitive& prim, const Mesh& m) const {
    if (prim.material >= 0 && scene_.materials[size_t(prim.material)].normal_texture.texcoord == 1 && !m.uv1.empty()) {
      return m.uv1;
    }
    return m.uv0;
  }

  uint32_t material_of(const tinygltf::Primitive& prim) {
    if (prim.material >= 0) return uint32_t(prim.material);
    if (default_material_ < 0) {
      Material d;  // glTF's default: white, metallic 1, roughness 1
      d.name = "default";
      default_material_ = int(scene_.materials.size());
      scene_.materials.push_back(d);
    }
    return uint32_t(default_material_);
  }

  void append(const Mesh& m, uint32_t material) {
    const uint32_t base = uint32_t(scene_.positions.size());
    const size_t n = m.pos.size();
    scene_.positions.insert(scene_.positions.end(), m.pos.begin(), m.pos.end());
    scene_.normals.insert(scene_.normals.end(), m.nrm.begin(), m.nrm.end());
    scene_.tangents.insert(scene_.tangents.end(), m.tan.begin(), m.tan.end());
    if (m.uv0.empty()) scene_.uv0.resize(scene_.uv0.size() + n, vec2(0.0f));
    else scene_.uv0.insert(scene_.uv0.end(), m.uv0.begin(), m.uv0.end());
    if (!m.uv1.empty()) any_uv1_ = true;
    if (!m.col.empty()) any_color_ = true;
    if (m.col.empty()) scene_.colors.resize(scene_.colors.size() + n, vec4(1.0f));
    else scene_.colors.insert(scene_.colors.end(), m.col.begin(), m.col.end());
    if (m.uv1.empty()) scene_.uv1.resize(scene_.uv1.size() + n, vec2(0.0f));
    else scene_.uv1.insert(scene_.uv1.end(), m.uv1.begin(), m.uv1.end());
    for (const uvec3& t : m.tris) {
      scene_.triangles.push_back(t + uvec3(base));
      scene_.triangle_material.push_back(material);
      for (uint32_t v : {t.x, t.y, t.z}) scene_.bounds.add(m.pos[v]);
    }
  }

  const Context& ctx_;
  Scene& scene_;
  std::vector<int> tangent_warned_;  // meshes already warned about generated tangents
  bool camera_found_ = false;
  bool any_uv1_ = false;
  bool any_color_ = false;
  int default_material_ = -1;
};

}  // namespace

void convert_nodes(const Context& ctx, Scene& scene) { Flattener(ctx, scene).run(); }

}  // namespace vct::gltf
