#include "compare/metamorphic.h"

#include <algorithm>

#include "core/error.h"
#include "scene/scene_transform.h"

namespace vct::cmp {

const std::vector<MetamorphicRow>& metamorphic_rows() {
  static const std::vector<MetamorphicRow> rows = {
      {"translate", "every position and the voxel volume moved by (3, -2, 5) voxels",
       "every stage unchanged, index by index (gbuffer.position moved by the same vector)",
       "the stage models of docs/compare.md: exact on the lattice but for the camera's and lights' "
       "view matrices, whose rounding moves clip coordinates by ulps (docs/metamorphic.md, "
       "Translation)",
       true, check_translate},
      {"shift_in_volume",
       "every position moved by k = (8, 8, 8) voxels (n/4 below 32^3), the volume fixed",
       "voxel volumes shifted by k, mip level L by k/2^L where whole (L <= 3); images that read no "
       "voxels "
       "unchanged; cone-traced images not compared (coarser levels move by fractions)",
       "the stage models of docs/compare.md; voxel stages exact where the voxelizer is translation-"
       "invariant on the grid (docs/metamorphic.md, Shift inside the volume)",
       true, check_shift_in_volume},
      {"turn_x",
       "scene, camera, emitters and volume turned +90 degrees about x (y -> z); spot lights and "
       "particles off in both frames",
       "volumes permuted index by index, mip.<d> from mip.<turn(d)>; images unchanged (diffuse "
       "cone "
       "stages only where the normal is an axis)",
       "the stage models of docs/compare.md; a sample-rule voxelizer sees the MSAA pattern "
       "mirrored "
       "(docs/metamorphic.md, Turns)",
       true, check_turn_x},
      {"turn_y", "turned +90 degrees about y (z -> x); spot lights and particles off", "as turn_x",
       "as turn_x", true, check_turn_y},
      {"turn_z",
       "turned +90 degrees about z (x -> y), spot lights on (the shadow maps' up, +z, is kept)",
       "as turn_x; shadow maps not compared (turned in their plane)", "as turn_x", true,
       check_turn_z},
      {"linearity", "every emission, spot intensity and particle colour doubled",
       "radiance stages (voxel RGB, mips RGB, direct, indirect, terms, emission, particles, final) "
       "doubled; "
       "opacity, depth, G-buffer (but emission) unchanged",
       "exact (scaling by 2 commutes with IEEE rounding) but for the fixed-point reduction (2 "
       "quanta), "
       "RGBA8 (1/255, saturation) and half storage (1 ulp) rounding values that differ, carried "
       "through "
       "the mips and cone steps (docs/metamorphic.md, Linearity)",
       true, check_linearity},
      {"furnace",
       "the white furnace (scenes/furnace_sphere.gltf, built in): albedo rho, emission Le, no "
       "light",
       "voxel RGB = Le x opacity, mips too (premultiplied), 0 <= indirect diffuse <= Le, "
       "Le <= final <= Le (1 + rho); the analytic one-bounce value Le (1 + rho) reported with "
       "VCT's bias",
       "storage rounding of Le; the bounds follow from front-to-back compositing of premultiplied "
       "samples (docs/metamorphic.md, Furnace)",
       false, check_furnace},
  };
  return rows;
}

int shift_voxels_for_grid(int n) {
  return n >= 32 ? 8 : std::max(1, n / 4);
}

std::string metamorphic_names() {
  std::string s;
  for (const MetamorphicRow& r : metamorphic_rows())
    s += (s.empty() ? "" : ", ") + std::string(r.name);
  return s;
}

Verdict overall_of(const std::vector<StageVerdict>& stages) {
  Report rep;
  rep.stages = stages;
  return rep.overall();
}

Verdict MetamorphicRun::overall() const {
  bool warn = false, any = false;
  for (const RelationResult& r : relations) {
    if (r.verdict == Verdict::Fail) return Verdict::Fail;
    warn = warn || r.verdict == Verdict::Warn;
    any = any || r.verdict != Verdict::Missing;
  }
  return !any ? Verdict::Missing : warn ? Verdict::Warn : Verdict::Pass;
}

void check_relation_names(const std::vector<std::string>& names) {
  for (const std::string& name : names) {
    const auto& rows = metamorphic_rows();
    if (std::none_of(rows.begin(), rows.end(),
                     [&](const MetamorphicRow& r) { return name == r.name; }))
      throw InputError("--only",
                       "unknown relation '" + name + "' (relations: " + metamorphic_names() + ")");
  }
}

MetamorphicRun run_metamorphic(const Scene& scene, const Settings& s, const FrameRenderer& render,
                               const std::vector<std::string>& only) {
  check_relation_names(only);
  auto wanted = [&](const MetamorphicRow& r) {
    return only.empty() || std::find(only.begin(), only.end(), r.name) != only.end();
  };
  MetamorphicRun run;
  const int shift = shift_voxels_for_grid(s.vct.grid);
  run.scene = on_voxel_lattice(scene, s.vct.grid, shift);
  const auto& rows = metamorphic_rows();
  if (std::any_of(rows.begin(), rows.end(),
                  [&](const MetamorphicRow& r) { return wanted(r) && r.needs_base; }))
    run.base = stage_set_from_frame(render(run.scene, s), s.vct);
  std::map<std::string, StageSet> variant_bases;
  const MetamorphicContext ctx{run.scene, s, render, run.base, shift, variant_bases};
  for (const MetamorphicRow& r : rows)
    if (wanted(r)) run.relations.push_back(r.run(ctx));
  return run;
}

nlohmann::json to_json(const RelationResult& r) {
  nlohmann::json stages = nlohmann::json::array();
  for (const StageVerdict& v : r.stages) stages.push_back(to_json(v));
  nlohmann::json j = {{"name", r.name},
                      {"verdict", to_string(r.verdict)},
                      {"note", r.note},
                      {"stages", stages},
                      {"extra", r.extra}};
  for (const MetamorphicRow& row : metamorphic_rows())
    if (r.name == row.name) {
      j["transform"] = row.transform;
      j["relation"] = row.relation;
      j["tolerance"] = row.tolerance;
    }
  return j;
}

}  // namespace vct::cmp
