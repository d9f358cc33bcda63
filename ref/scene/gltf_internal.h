// Pieces of the glTF loader shared between its files (not a public API): the file name used in
// every message, the checks run on a parsed tinygltf model, typed accessor reads, and the
// conversion of materials, nodes, lights and particles into the Scene model.
#pragma once

#include <string>
#include <vector>

#include <tiny_gltf.h>

#include "core/error.h"
#include "scene/scene.h"

namespace vct::gltf {

/// Everything the conversion needs to know about where the model came from.
struct Context {
  const tinygltf::Model& model;
  std::string file;  // name used in messages
};

/// Throws InputError(ctx.file, message).
[[noreturn]] void fail(const Context& ctx, const std::string& message);

/// The extensions we understand; a file requiring any other is refused.
const std::vector<std::string>& supported_extensions();

/// Checks every index, byte range, the node graph (a forest: no cycles, one parent per node)
/// and required extensions. Throws InputError on the first problem.
void validate_model(const Context& ctx);

/// Reads accessor `index` as floats, `components` per element (VEC2 = 2 ...); normalized
/// integer types are converted as glTF defines, sparse substitutions applied. Throws on NaN/Inf
/// (`what` names the attribute).
std::vector<float> read_floats(const Context& ctx, int index, int components, const std::string& what);

/// The substituted element indices of a sparse accessor (glTF 2.0 §3.6.2.3), unchecked.
std::vector<uint32_t> read_sparse_indices(const Context& ctx, const tinygltf::Accessor& a);

/// Reads an index accessor (UNSIGNED_BYTE/SHORT/INT), sparse substitutions applied.
std::vector<uint32_t> read_indices(const Context& ctx, int index, const std::string& what);

/// The default morph weights of `node` showing `mesh`: the node's, else the mesh's (gltf_morph.cpp).
std::vector<float> morph_weights(const Context& ctx, int node, int mesh);

/// Adds Σ weights[t] · target[t][attribute] to `values` (`components` floats per vertex, the
/// target's data read as the attribute's own type: POSITION/NORMAL VEC3, TANGENT VEC3 per the spec).
void add_morph_displacements(const Context& ctx, const tinygltf::Primitive& prim, const std::vector<float>& weights,
                             const std::string& attribute, int components, std::vector<float>& values,
                             const std::string& owner);

/// Materials and textures, converted once. Adds warnings for unsupported features.
void convert_textures(const Context& ctx, Scene& scene);
void convert_materials(const Context& ctx, Scene& scene);

/// Walks the default scene's node trees and appends geometry, camera, lights and particle
/// emitters in world space.
void convert_nodes(const Context& ctx, Scene& scene);

/// Node-attached objects (gltf_objects.cpp). `world` is the node's world matrix.
Camera make_camera(const Context& ctx, int camera, const mat4& world);
Light make_light(const Context& ctx, int light, const mat4& world);
/// Checks every light: a KHR_lights_punctual type (spot, point, directional), spot cone angles,
/// finite non-negative intensity, range and colour.
void validate_lights(const Context& ctx);
/// One warning per spot light with innerConeAngle == outerConeAngle (rendered as a step).
void warn_hard_spots(const Context& ctx, std::vector<std::string>& warnings);
/// "material N 'Name': KHR_materials_X ignored, <what is rendered instead>", one per extension the
/// material carries that no engine applies (gltf_material_extensions.cpp).
void warn_material_extensions(const tinygltf::Material& g, const std::string& owner, std::vector<std::string>& warnings);
/// What is rendered instead of a KHR_materials_* extension ("rendered opaque with its base colour").
std::string material_extension_instead(const std::string& extension);
/// extras.vct_particles of node `node`, if present.
bool read_particles(const Context& ctx, int node, const mat4& world, ParticleEmitter& out);

/// The optional `vct_volume` override in asset or scene extras; false when absent.
bool read_volume_override(const Context& ctx, VoxelVolume& volume);

}  // namespace vct::gltf
