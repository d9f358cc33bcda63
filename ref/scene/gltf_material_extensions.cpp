// What the renderers do instead of a KHR_materials_* extension they do not model, one row per
// extension (docs/scenes.md, "Warnings"): the user reads which material lost what, and what it looks
// like now ("material 'Glass': KHR_materials_transmission ignored, rendered opaque with its base colour").
#include <string>
#include <utility>
#include <vector>

#include "scene/gltf_internal.h"

namespace vct::gltf {

namespace {

const std::vector<std::pair<const char*, const char*>>& instead_table() {
  static const std::vector<std::pair<const char*, const char*>> rows{
      {"KHR_materials_transmission", "rendered opaque with its base colour"},
      {"KHR_materials_diffuse_transmission", "rendered opaque (no light through it)"},
      {"KHR_materials_volume", "rendered as a surface (no absorption inside)"},
      {"KHR_materials_clearcoat", "rendered without its clear coat (base layer only)"},
      {"KHR_materials_sheen", "rendered without sheen"},
      {"KHR_materials_ior", "rendered with IOR 1.5 (F0 0.04)"},
      {"KHR_materials_iridescence", "rendered without iridescence"},
      {"KHR_materials_anisotropy", "rendered with isotropic roughness"},
      {"KHR_materials_dispersion", "rendered without dispersion"},
      {"KHR_materials_unlit", "rendered lit (metallic-roughness PBR)"},
  };
  return rows;
}

// Extensions a material carries that the renderers apply (docs/scenes.md, "Extensions").
bool applied(const std::string& name) {
  return name == "KHR_materials_emissive_strength" || name == "KHR_materials_specular" ||
         name == "KHR_texture_transform";
}

}  // namespace

std::string material_extension_instead(const std::string& extension) {
  for (const auto& [name, instead] : instead_table())
    if (extension == name) return instead;
  return "rendered without it";
}

void warn_material_extensions(const tinygltf::Material& g, const std::string& owner, std::vector<std::string>& warnings) {
  for (const auto& [name, value] : g.extensions) {
    if (applied(name)) continue;
    warnings.push_back(owner + ": " + name + " ignored, " + material_extension_instead(name));
  }
}

}  // namespace vct::gltf
