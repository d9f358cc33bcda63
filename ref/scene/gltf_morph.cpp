// Morph targets at their default weights (glTF 2.0 §3.7.2.2): a still frame renders
// base + Σ weights[i] · target[i] for each attribute a target displaces. The weights are the node's
// when it has them, else the mesh's, else zero (no displacement).
#include "scene/gltf_internal.h"

namespace vct::gltf {

std::vector<float> morph_weights(const Context& ctx, int node, int mesh) {
  const auto& n = ctx.model.nodes[size_t(node)];
  const auto& m = ctx.model.meshes[size_t(mesh)];
  const std::vector<double>& w = !n.weights.empty() ? n.weights : m.weights;
  return std::vector<float>(w.begin(), w.end());
}

void add_morph_displacements(const Context& ctx, const tinygltf::Primitive& prim, const std::vector<float>& weights,
                             const std::string& attribute, int components, std::vector<float>& values,
                             const std::string& owner) {
  if (prim.targets.empty()) return;
  if (weights.size() > prim.targets.size()) {
    fail(ctx, owner + " has " + std::to_string(prim.targets.size()) + " morph targets but " +
                  std::to_string(weights.size()) + " weights");
  }
  for (size_t t = 0; t < weights.size(); ++t) {
    const auto it = prim.targets[t].find(attribute);
    if (it == prim.targets[t].end() || weights[t] == 0.0f) continue;
    const std::string what = owner + " morph target " + std::to_string(t) + " " + attribute;
    const std::vector<float> d = read_floats(ctx, it->second, components, what);
    if (d.size() != values.size()) fail(ctx, what + " count differs from the primitive's " + attribute + " count");
    for (size_t i = 0; i < values.size(); ++i) values[i] += weights[t] * d[i];
  }
}

}  // namespace vct::gltf
