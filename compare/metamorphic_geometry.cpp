// The geometric relations (docs/metamorphic.md): moving the scene with its volume, shifting it by
// whole voxels inside a fixed volume, turning it by 90 degrees. Each renders one transformed
// frame, maps it back (metamorphic_map.h) and judges it against the base frame with the stage
// comparison's own tolerance models (docs/compare.md): the two frames differ only by the rounding
// of positions, which is inside every freedom those models allow.
#include <algorithm>
#include <cstdio>

#include "compare/metamorphic.h"
#include "compare/metamorphic_map.h"
#include "compare/stage_compare.h"
#include "scene/scene_transform.h"

namespace vct::cmp {

namespace {

float voxel_size(const MetamorphicContext& c) {
  return c.scene.volume.size / float(c.settings.vct.grid);
}

StageSet render_set(const MetamorphicContext& c, const Scene& scene) {
  return stage_set_from_frame(c.render(scene, c.settings), c.settings.vct);
}

// The base frame as the reference, the mapped-back frame as the test, on the stages both hold.
RelationResult judge_against_base(const std::string& name, const StageSet& base_set,
                                  const StageSet& mapped) {
  RelationResult r;
  r.name = name;
  const StageSet base = common_stages(base_set, mapped);
  const StageSet test = common_stages(mapped, base_set);
  const Report rep = compare_stage_sets(base, test);
  for (const StageVerdict& v : rep.stages)
    if (v.verdict != Verdict::Missing) r.stages.push_back(v);
  r.verdict = overall_of(r.stages);
  size_t failing = 0, warning = 0;
  for (const StageVerdict& v : r.stages)
    failing += v.verdict == Verdict::Fail, warning += v.verdict == Verdict::Warn;
  char b[256];
  std::snprintf(
      b, sizeof b, "%zu stages compared: %zu fail, %zu warn%s%s", r.stages.size(), failing, warning,
      rep.first_failing().empty() ? "" : "; first failing: ", rep.first_failing().c_str());
  r.note = b;
  r.sets["base"] = base;
  r.sets["mapped"] = test;
  return r;
}

// What a turn cannot keep, left out of both frames: particles (each axis of a particle draws its
// own random number, vct_shared.h particle_state: a turn hands them to other axes); for turns
// about x and y, the spot lights (a shadow map's up vector is world +z, stages/shadow_map.cpp:
// turned about x or y, a light's map turns in its own plane and PCF samples another texel grid);
// and the sample rule's 4 or 8 MSAA samples (the standard patterns are not mirror-symmetric and a
// turn mirrors some projection planes: coverage ties), replaced by one sample at the pixel centre,
// which a mirror keeps.
struct TurnScene {
  Scene scene;
  Settings settings;
  std::string key;   // "" = the base scene itself
  std::string what;  // what both frames leave out, for the note
};

TurnScene turn_scene(const MetamorphicContext& c, int axis) {
  TurnScene t{c.scene, c.settings, "", ""};
  if (!c.scene.emitters.empty() && c.settings.vct.particles) {
    t.settings.vct.particles = false;
    t.key = "no_particles";
    t.what = "no particles";
  }
  auto also = [&t](const std::string& key, const std::string& what) {
    t.key += (t.key.empty() ? "" : "_") + key;
    t.what += (t.what.empty() ? "" : ", ") + what;
  };
  // Spot and directional shadow maps take their up from world +z (shadow_map.cpp, light_up), so
  // they turn with the scene about z only; a point light's cube faces are fixed to the world axes.
  std::vector<Light>& lights = t.scene.lights;
  const auto fixed = [axis](const Light& l) { return l.is_point() || axis != 2; };
  if (std::any_of(lights.begin(), lights.end(), fixed)) {
    lights.erase(std::remove_if(lights.begin(), lights.end(), fixed), lights.end());
    also("unlit", axis != 2 ? "no lights" : "no point lights");
  }
  if (c.settings.vct.voxelizer == Voxelizer::GpuEmulation && c.settings.vct.msaa_samples != 1) {
    t.settings.vct.msaa_samples = 1;
    also("msaa1", "one MSAA sample");
  }
  return t;
}

const StageSet& turn_base(const MetamorphicContext& c, const TurnScene& t) {
  if (t.key.empty()) return c.base;
  auto it = c.variant_bases.find(t.key);
  if (it == c.variant_bases.end())
    it = c.variant_bases
             .emplace(t.key, stage_set_from_frame(c.render(t.scene, t.settings), t.settings.vct))
             .first;
  return it->second;
}

// The diffuse cone count whose quarter-turn symmetry keep_turn_invariant_cones may rely on: an
// engine's declared set or the source design's tangent frame promises none (0: every pixel's
// cones are left out of the turn relation).
int turn_symmetric_cone_count(const VctSettings& s) {
  if (!s.diffuse_cone_set.empty() || s.cone_tangent_frame != ConeTangentFrame::Branchless) return 0;
  return s.diffuse_cone_count;
}

RelationResult check_turn(const MetamorphicContext& c, int axis, const char* name) {
  const TurnScene t = turn_scene(c, axis);
  const StageSet& base = turn_base(c, t);
  StageSet mapped = unturned(
      stage_set_from_frame(c.render(turned90(t.scene, axis), t.settings), t.settings.vct), axis);
  const size_t left_out =
      c.settings.vct.diffuse_cones
          ? keep_turn_invariant_cones(mapped, base, turn_symmetric_cone_count(c.settings.vct))
          : 0;
  RelationResult r = judge_against_base(name, base, mapped);
  r.extra["axis"] = std::string(1, "xyz"[axis]);
  r.extra["diffuse_cone_pixels_not_judged"] = left_out;
  r.extra["variant"] = t.key;
  if (!t.key.empty())
    r.sets["variant_base"] = base;  // not the shared base: written beside the relation
  if (left_out) {
    char b[160];
    std::snprintf(
        b, sizeof b,
        "; diffuse cone stages not judged at %zu pixels (normal off the axes: cone frame)",
        left_out);
    r.note += b;
  }
  if (!t.key.empty()) r.note += "; both frames: " + t.what;
  return r;
}

}  // namespace

RelationResult check_translate(const MetamorphicContext& c) {
  // Odd, mixed-sign whole voxels: every voxel keeps its index since the volume moves too.
  const ivec3 k(3, -2, 5);
  const vec3 t = vec3(k) * voxel_size(c);
  RelationResult r = judge_against_base(
      "translate", c.base, untranslated(render_set(c, translated(c.scene, t, true)), t));
  r.extra["voxels"] = {k.x, k.y, k.z};
  return r;
}

RelationResult check_shift_in_volume(const MetamorphicContext& c) {
  const ivec3 k(c.shift_voxels);
  const vec3 t = vec3(k) * voxel_size(c);
  const StageSet shifted = render_set(c, translated(c.scene, t, false));
  RelationResult r = judge_against_base("shift_in_volume", c.base,
                                        unshifted(shifted, k, t, c.settings.vct.soft_shadows));
  r.extra["voxels"] = {k.x, k.y, k.z};
  return r;
}

RelationResult check_turn_x(const MetamorphicContext& c) {
  return check_turn(c, 0, "turn_x");
}
RelationResult check_turn_y(const MetamorphicContext& c) {
  return check_turn(c, 1, "turn_y");
}
RelationResult check_turn_z(const MetamorphicContext& c) {
  return check_turn(c, 2, "turn_z");
}

}  // namespace vct::cmp
