// Checkpoints of a path-traced render: the accumulators after whole passes, the pass count and
// the hashes of the scene and of the settings that shape the image, so a resumed or refined
// render continues exactly where the interrupted one stopped (format: docs/pathtracer.md).
#pragma once

#include <cstdint>
#include <string>

#include "core/settings.h"
#include "pt/accumulator.h"
#include "pt/particle_lights.h"
#include "scene/scene.h"

namespace vct::pt {

/// FNV-1a 64 over the scene's geometry, attributes, materials, textures, lights and camera.
uint64_t hash_scene(const Scene& scene);
/// Hash of the PtSettings that change the image (all but spp and checkpoint_seconds).
uint64_t hash_pt_settings(const PtSettings& s);
/// hash_pt_settings combined with the particle options (they change the image too).
uint64_t hash_render_settings(const PtSettings& s, const ParticleOptions& p);

struct CheckpointKey {
  uint64_t scene_hash = 0;
  uint64_t settings_hash = 0;
};

/// Writes the checkpoint atomically (temporary file + rename).
void save_checkpoint(const std::string& path, const CheckpointKey& key, const Accumulator& acc);

/// Loads a checkpoint into `acc` if the file exists and matches key and image size. Returns
/// false (and says why in `why`) when there is none or it belongs to another scene/settings.
bool load_checkpoint(const std::string& path, const CheckpointKey& key, int width, int height, Accumulator& acc,
                     std::string& why);

}  // namespace vct::pt
