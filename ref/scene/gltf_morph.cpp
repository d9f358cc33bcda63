// Morph targets at their default weights (glTF 2.0 §3.7.2.2): a still frame renders
// base + Σ weights[i] · target[i] for each attribute a target displaces. The weights are the node's
// when it has them, else the mesh's, else zero (no displacement).
#include <cmath>

#include "scene/gltf_internal.h"

namespace vct::gltf {

std::vector<float> morph_weights(const Context& ctx, int node, int mesh) {
  const auto& n = ctx.model.nodes[size_t(node)];
  const auto& m = ctx.model.meshes[size_t(mesh)];
  const std::vector<double>& w = !n.weights.empty() ? n.weights : m.weights;
  const std::vector<float> out(w.begin(), w.end());
  for (size_t i = 0; i < out.size(); ++i) {
    if (!std::isfinite(out[i])) {
      fail(ctx, "node " + std::to_string(node) + " (mesh " + std::to_string(mesh) + ") morph weight " + std::to_string(i) +
                    " is not a finite float");
    }
  }
  return out;
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
    for (size_t i = 0; i < values.size(); ++i) {
      values[i] += weights[t] * d[i];
      if (!std::isfinite(values[i])) {
        fail(ctx, what + " (weight " + std::to_string(weights[t]) + ") makes element " + std::to_string(i / size_t(components)) +
                      " of " + attribute + " non-finite (overflows float)");
      }
    }
  }
}

}  // namespace vct::gltf
