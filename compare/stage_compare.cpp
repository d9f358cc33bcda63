// The judge's first pass: every stage of two sets in pipeline order, dispatched to its family's
// judge (image_judge.cpp, the volume judges), each element admitted by a rule of the admission
// table (compare/admission.h).
#include "stage_compare.h"

#include <algorithm>
#include <optional>

#include "compare/bounce_frames.h"
#include "compare/isolated_stages.h"
#include "compare/tie_range.h"
#include "compare/volume_judges.h"
#include "stages/shadow_map.h"
#include "stages/stage_registry.h"

namespace vct::cmp {

namespace {

namespace st = stage_names;

// A stage the reference has and the test lacks is "missing" (an engine dumps what it can), except
// within a family the test does have: a mip chain that stops short, or one light's shadow map of
// several, is a bug of the test (the settings fix the levels and the scene the lights).
bool chain_broken(const StageSet& ts, const std::optional<StageRef>& ref) {
  if (!ref || ref->row->index == StageIndex::None) return false;
  auto same_family = [&](const std::string& name) {
    const auto other = find_stage(name);
    return other && other->row == ref->row;
  };
  for (const auto& kv : ts.images)
    if (same_family(kv.first)) return true;
  for (const auto& kv : ts.volumes)
    if (same_family(kv.first)) return true;
  return false;
}

StageVerdict broken_chain(const std::string& stage, const StageSet& ts, const std::optional<StageRef>& ref) {
  StageVerdict v;
  v.stage = stage;
  v.verdict = Verdict::Fail;
  v.model = "required-stage";
  v.bound = "every member of a family the test produces (mip levels down to 1^3, one shadow map per light)";
  v.note = ts.backend + " has other " + std::string(ref->row->name) + " members but not this one (a chain that stops short)";
  return v;
}

// One step of the reference's shadow depth format (its manifest settings; absent = float).
double depth_quantum_of(const StageSet& rs) {
  if (!rs.settings.is_object() || !rs.settings.contains("shadow_depth_format")) return 0.0;
  const nlohmann::json& format = rs.settings.at("shadow_depth_format");
  for (ShadowDepthFormat f : {ShadowDepthFormat::Depth24, ShadowDepthFormat::Depth16})
    if (format == to_string(f)) return depth_quantum(f);
  return 0.0;
}

// The voxel stages also hand the cone stages after them the share of voxels that tie (taint).
struct VoxelTaint {
  Taint occupancy, radiance, both;
};

StageVerdict judge_voxel_stage(ToleranceModel model, const StageSet& rs, const StageSet& ts, const CompareOptions& opt,
                               JudgeContext& ctx, VoxelTaint& taint) {
  if (!rs.volumes.count(st::kVoxelRadiance) || !ts.volumes.count(st::kVoxelRadiance))
    return missing_stage(model == ToleranceModel::VoxelOccupancy ? st::kVoxelOccupancy : st::kVoxelRadiance,
                         "voxel radiance missing on one side");
  if (model == ToleranceModel::VoxelOccupancy) {
    StageVerdict v = compare_occupancy(rs, ts, opt, taint.occupancy);
    taint.both = taint.occupancy;
    return v;
  }
  StageVerdict v = compare_radiance(rs, ts, opt, ctx, taint.radiance);
  taint.both.resize(std::max(taint.both.size(), taint.radiance.size()), 0);
  for (size_t i = 0; i < taint.radiance.size(); ++i) taint.both[i] |= taint.radiance[i];
  size_t tainted = 0, occupied = 0;
  for (uint8_t t : taint.both) tainted += t;
  for (uint8_t o : occupancy(rs.volumes.at(st::kVoxelRadiance))) occupied += o;
  ctx.upstream_tie_fraction = occupied ? double(tainted) / double(occupied) : 0.0;
  return v;
}

// The reference side's image as linear light. A reference that is itself an engine's dump may
// declare a display transform (two runs of one engine compared, issue 39): its stored image is
// decoded through that transform's inverse (decode_display_direct) and then judged like any
// linear reference, through the test's transform when it declares one. A transform with no
// inverse (aces, gamma < 1) that both sides declare alike leaves both images as stored and
// compares them with no transform.
const Image& reference_in_linear(const std::string& stage, const StageSet& rs, ImageStageInputs& in,
                                 Image& decoded) {
  const Image& stored = rs.images.at(stage);
  const DisplayTransform& own = rs.conventions.display;
  if (!own.declared() || !own.applies_to(stage)) return stored;
  if (own.decodable()) {
    decoded = stored;
    decode_display_direct(own, decoded);
    in.reference_quantisation = own.quantisation_allowance();
    return decoded;
  }
  if (in.display && to_json(*in.display) == to_json(own)) in.display = nullptr;
  return stored;
}

// An image stage with the images its rules read: the camera's depth (edges), the reference's
// texture slack and raster alternatives; a shadow map is its own depth and has its own range
// (freedoms/shadow_map_ties.h; without one, an external reference, it keeps the neighbourhood rule
// and the shares).
StageVerdict judge_image(const std::string& stage, const std::optional<StageRef>& ref, const StageSet& rs,
                         const StageSet& ts, const CompareOptions& opt, const JudgeContext& ctx) {
  auto image = [&](const char* name) { return rs.images.count(name) ? &rs.images.at(name) : nullptr; };
  const bool light_space = ref && (ref->row->index == StageIndex::Light || ref->row->index == StageIndex::CubeFace);
  JudgeContext stage_ctx = ctx;
  if (light_space) stage_ctx.depth_quantum = depth_quantum_of(rs);
  ImageStageInputs in;
  in.edge_hint = light_space ? nullptr : image(st::kGbufferDepth);
  in.texture_slack = image(st::kGbufferTextureSlack);
  in.display = ts.conventions.display.applies_to(stage) ? &ts.conventions.display : nullptr;
  const auto own_range = light_space ? rs.images.find(tie_range_stage(stage)) : rs.images.end();
  in.tie_range = !light_space ? image(st::kGbufferTieRange) : own_range != rs.images.end() ? &own_range->second : nullptr;
  Image decoded;
  const Image& reference = reference_in_linear(stage, rs, in, decoded);
  return judge_image_stage(stage, reference, ts.images.at(stage), in, opt, stage_ctx);
}

}  // namespace

Report compare_stage_sets(const StageSet& rs, const StageSet& ts, const CompareOptions& opt,
                          const JudgeContext& ctx_in) {
  Report rep;
  JudgeContext ctx = ctx_in;
  ctx.soft_shadows = soft_shadows_of(rs) || soft_shadows_of(ts);
  VoxelTaint taint;
  for (const std::string& stage : pipeline_order(rs, ts)) {
    const auto ref = find_stage(stage);
    const ToleranceModel model = ref ? ref->row->model : ToleranceModel::None;
    const bool r_has = rs.has(stage), t_has = ts.has(stage);
    if (model == ToleranceModel::VoxelFrame || model == ToleranceModel::VoxelEnergy)
      // A multibounce frame's voxels depend on its previous frame: judged only on the test's own
      // (compare/bounce_frames.h, the judge's third pass); here it waits for that pass.
      rep.stages.push_back(missing_stage(stage, t_has || model == ToleranceModel::VoxelEnergy
                                                    ? kBounceFramesNeedTheScene
                                                    : "not produced by " + ts.backend));
    else if (model == ToleranceModel::VoxelOccupancy || model == ToleranceModel::VoxelRadiance)
      rep.stages.push_back(judge_voxel_stage(model, rs, ts, opt, ctx, taint));
    else if (model == ToleranceModel::VoxelHoles)
      rep.stages.push_back(compare_holes(rs, ts, opt));
    else if (!r_has || !t_has)
      rep.stages.push_back(r_has && chain_broken(ts, ref)
                               ? broken_chain(stage, ts, ref)
                               : missing_stage(stage, std::string("not produced by ") + (r_has ? ts.backend : rs.backend)));
    else if (rs.images.count(stage))
      rep.stages.push_back(judge_image(stage, ref, rs, ts, opt, ctx));
    else if (model == ToleranceModel::Mip)  // bounds and taint are taken on the reference's level 0
      rep.stages.push_back(rs.volumes.count(st::kVoxelRadiance)
                               ? compare_mip(stage, rs, ts, opt, taint.both)
                               : missing_stage(stage, "the reference's voxel.radiance is missing"));
    else
      rep.stages.push_back(compare_volume_plain(stage, rs.volumes.at(stage), ts.volumes.at(stage), 1e-6, 1e-5, opt));
  }
  return rep;
}

Report compare_stage_sets(const StageSet& rs, const StageSet& ts, const CompareOptions& opt) {
  return compare_stage_sets(rs, ts, opt, JudgeContext());
}

}  // namespace vct::cmp
