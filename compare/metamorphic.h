// Metamorphic checks (docs/metamorphic.md): relations between frames of one backend that hold
// whatever its conventions, so a VCT implementation is judged without a CPU reference. One row
// per relation: its name, the transform of the scene or settings, the relation, its tolerance.
#pragma once

#include <functional>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "compare/stage_set.h"
#include "compare/verdict.h"
#include "core/settings.h"
#include "scene/scene.h"
#include "stages/stage_types.h"

namespace vct::cmp {

/// Renders one frame with the backend under test.
using FrameRenderer = std::function<FrameResult(const Scene&, const Settings&)>;

/// One relation's outcome: a verdict per compared stage and what was compared.
struct RelationResult {
  std::string name;
  Verdict verdict = Verdict::Missing;
  std::vector<StageVerdict> stages;  // pipeline order
  std::string note;                  // one line for the human (numbers, worst stage)
  nlohmann::json extra = nlohmann::json::object();
  // The frames compared, in the base scene's coordinates ("base" is the reference side,
  // "mapped" the transformed frame mapped back), for the run directory.
  std::map<std::string, StageSet> sets;
};

/// What every relation reads: the scene on its voxel lattice, the settings, the backend, and
/// the base frame (rendered once, shared by the relations that compare against it).
struct MetamorphicContext {
  const Scene& scene;
  const Settings& settings;
  const FrameRenderer& render;
  const StageSet& base;
  int shift_voxels = 8;  // the whole-voxel shift inside the volume, per axis
  // Base frames of scene variants (the turns' unlit or particle-free scene), rendered once.
  std::map<std::string, StageSet>& variant_bases;
};

struct MetamorphicRow {
  const char* name;       // "translate", "shift_in_volume", "turn_x", "linearity", "furnace", ...
  const char* transform;  // what changes in the scene or the settings
  const char* relation;   // what must hold
  const char* tolerance;  // the bound and where it comes from (docs/metamorphic.md)
  bool needs_base;        // compares against the lattice scene's base frame
  RelationResult (*run)(const MetamorphicContext&);
};

/// Every relation, in the order they run.
const std::vector<MetamorphicRow>& metamorphic_rows();

/// The whole-voxel shift inside the volume for a grid of n: 8 voxels (mip levels 0..3 move by
/// whole voxels), n/4 below n = 32.
int shift_voxels_for_grid(int n);

struct MetamorphicRun {
  Scene scene;  // the scene on its voxel lattice (scene/scene_transform.h)
  StageSet base;
  std::vector<RelationResult> relations;
  Verdict overall() const;  // Fail if any relation fails, else Warn if any warns, else Pass
};

/// Runs the relations named in `only` (empty = all) with `render`. Throws InputError for an
/// unknown relation name.
MetamorphicRun run_metamorphic(const Scene& scene, const Settings& s, const FrameRenderer& render,
                               const std::vector<std::string>& only = {});

/// Comma-separated relation names (messages, --help).
std::string metamorphic_names();

/// Throws InputError("--only", ...) for a name that is not a relation.
void check_relation_names(const std::vector<std::string>& names);

nlohmann::json to_json(const RelationResult& r);

// The relations (one file each: metamorphic_geometry.cpp, metamorphic_linearity.cpp,
// metamorphic_furnace.cpp).
RelationResult check_translate(const MetamorphicContext& c);
RelationResult check_shift_in_volume(const MetamorphicContext& c);
RelationResult check_turn_x(const MetamorphicContext& c);
RelationResult check_turn_y(const MetamorphicContext& c);
RelationResult check_turn_z(const MetamorphicContext& c);
RelationResult check_linearity(const MetamorphicContext& c);
RelationResult check_furnace(const MetamorphicContext& c);

/// The verdict of a list of stage verdicts (Missing ones ignored).
Verdict overall_of(const std::vector<StageVerdict>& stages);

}  // namespace vct::cmp
