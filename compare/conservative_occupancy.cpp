#include "compare/conservative_occupancy.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/error.h"
#include "scene/scene.h"
#include "stages/stage_registry.h"
#include "stages/voxelize.h"

namespace vct::cmp {
namespace st = stage_names;

ConservativeBound conservative_bound(const BackendFacts& facts, const std::string& where) {
  ConservativeBound b;
  b.mode = facts.conservative_mode;
  if (b.mode.empty()) return b;
  if (b.mode == "gs") {
    // The bounding quad covers every pixel centre whose square meets the triangle's box (with a
    // 1/16-pixel margin for snapping and the fill rule); the fragment shader then clips the
    // triangle to the closed pixel square exactly. Only GL's arithmetic is left.
    b.over = b.under = kConservativeArithmetic;
    b.source = "GS bounding quad + exact clip in the fragment shader: GL's double arithmetic (GLSL 4.50 §4.7.1 "
               "promises float precision) on the same float vertices";
    return b;
  }
  if (b.mode != "nv" && b.mode != "intel") throw InputError(where, "facts: unknown conservative_mode '" + b.mode + "'");
  if (facts.conservative_snap_bits < 1)
    throw InputError(where, "facts: conservative_mode " + b.mode + " without conservative_snap_bits");
  // Hardware rasterizes the triangle after snapping its window coordinates to 2^-bits; each vertex
  // moves by less than that per axis, so every point of the triangle does too: the pixels it
  // generates are those the snapped triangle touches (NV_conservative_raster), within 2^-bits of
  // the exact triangle's, plus the dilation (NV_conservative_raster_dilate; default 0).
  const double snap = std::ldexp(1.0, -facts.conservative_snap_bits);
  b.over = snap + facts.conservative_dilation + kConservativeArithmetic;
  b.under = snap + kConservativeArithmetic;
  char s[200];
  std::snprintf(s, sizeof s, "%s hardware conservative raster after snapping to 2^-%d px, dilation %g px, + GL's "
                "shader arithmetic", b.mode.c_str(), facts.conservative_snap_bits, facts.conservative_dilation);
  b.source = s;
  return b;
}

std::vector<VoxelTriangle> voxel_space_triangles(const Scene& scene, int n) {
  std::vector<VoxelTriangle> out;
  out.reserve(scene.triangles.size());
  for (const uvec3& t : scene.triangles)
    out.push_back({to_voxel_space(scene, n, scene.positions[t.x]), to_voxel_space(scene, n, scene.positions[t.y]),
                   to_voxel_space(scene, n, scene.positions[t.z])});
  return out;
}

bool any_triangle_meets_voxel(const std::vector<VoxelTriangle>& tris, const ivec3& voxel, double grow) {
  const glm::dvec3 lo = glm::dvec3(voxel) - grow, hi = glm::dvec3(voxel) + 1.0 + grow;
  for (const VoxelTriangle& t : tris) {
    const glm::dvec3 tlo = glm::min(t[0], glm::min(t[1], t[2])), thi = glm::max(t[0], glm::max(t[1], t[2]));
    if (glm::any(glm::lessThan(thi, lo)) || glm::any(glm::greaterThan(tlo, hi))) continue;
    if (triangle_meets_box(t.data(), lo, hi)) return true;
  }
  return false;
}

namespace {

bool occupied(const Volume& v, size_t i) { return v.data[i * size_t(v.channels) + size_t(v.channels - 1)] > 0.0f; }

Offender voxel_offender(int x, int y, int z, bool in_exact, bool in_test) {
  Offender o;
  o.at = {x, y, z};
  o.reference = {in_exact ? 1.0f : 0.0f};
  o.test = {in_test ? 1.0f : 0.0f};
  o.error = 1.0f;
  o.bound = 0.0f;
  return o;
}

std::string bound_words(const ConservativeBound& b) {
  char s[400];
  std::snprintf(s, sizeof s,
                "every exact (triangle-box) voxel present, except where no triangle meets its box shrunk by %.6g "
                "voxel (tie, warn); an extra voxel only where a triangle meets its box grown by %.6g voxel (%s)",
                b.under, b.over, b.source.c_str());
  return s;
}

}  // namespace

StageVerdict judge_conservative_occupancy(const Volume& exact, const Volume& test, const std::vector<VoxelTriangle>& tris,
                                          const ConservativeBound& bound, size_t worst_n) {
  StageVerdict v;
  v.stage = st::kVoxelOccupancy;
  v.model = "conservative-superset";
  v.bound = bound_words(bound);
  if (exact.nx != test.nx || exact.ny != test.ny || exact.nz != test.nz) {
    v.verdict = Verdict::Fail;
    v.note = "grid sizes differ: " + std::to_string(exact.nx) + " vs " + std::to_string(test.nx);
    return v;
  }
  size_t missing = 0, extra = 0, ties = 0, unchecked = 0, hard = 0, hard_missing = 0, occupied_exact = 0;
  std::vector<Offender> offenders;
  for (int z = 0; z < exact.nz; ++z)
    for (int y = 0; y < exact.ny; ++y)
      for (int x = 0; x < exact.nx; ++x) {
        const size_t i = (size_t(z) * size_t(exact.ny) + size_t(y)) * size_t(exact.nx) + size_t(x);
        const bool e = occupied(exact, i), t = occupied(test, i);
        occupied_exact += e;
        if (e == t) continue;
        bool admitted;
        if (e) {  // missing: only a triangle that barely touches the voxel may be lost to snapping
          ++missing;
          admitted = !tris.empty() && !any_triangle_meets_voxel(tris, {x, y, z}, -bound.under);
        } else {
          ++extra;
          if (tris.empty()) {
            ++unchecked;
            continue;
          }
          admitted = any_triangle_meets_voxel(tris, {x, y, z}, bound.over);
        }
        if (admitted) {
          ++ties;
          continue;
        }
        ++hard;
        hard_missing += e;
        offenders.push_back(voxel_offender(x, y, z, e, t));
      }
  v.checked = exact.voxel_count();
  v.out_of_bound = missing + extra;
  v.allowed = ties + unchecked;
  v.max_abs = v.out_of_bound ? 1.0 : 0.0;
  v.verdict = hard ? Verdict::Fail : (ties || unchecked) ? Verdict::Warn : Verdict::Pass;
  v.note = std::to_string(occupied_exact) + " occupied in the exact set; " + std::to_string(missing) + " missing, " +
           std::to_string(extra) + " extra (" + std::to_string(ties) + " within the bound";
  if (unchecked) v.note += ", " + std::to_string(unchecked) + " extra not checked: no scene (--scene SCENE)";
  v.note += ")";
  if (hard) {
    const Offender& o = offenders.front();
    v.note += "; first beyond: voxel (" + std::to_string(o.at[0]) + "," + std::to_string(o.at[1]) + "," +
              std::to_string(o.at[2]) + ") " + (o.reference[0] > 0.0f ? "missing" : "extra");
  }
  v.extra = {{"occupied_exact", occupied_exact}, {"missing", missing}, {"extra", extra}, {"ties", ties},
             {"missing_beyond", hard_missing}, {"extra_beyond", hard - hard_missing},
             {"unchecked", unchecked}, {"over", bound.over}, {"under", bound.under}, {"mode", bound.mode}};
  keep_worst(offenders, worst_n);
  v.worst = std::move(offenders);
  return v;
}

namespace {

// The surface occupancy of a set: voxels holding fragments where the set has the count (filled
// voxels of solid voxelization / thickening are not the voxelizer's), else opaque voxels.
const Volume* surface_volume(const StageSet& s) {
  auto f = s.volumes.find(st::kVoxelFragments);
  if (f != s.volumes.end()) return &f->second;
  auto r = s.volumes.find(st::kVoxelRadiance);
  return r != s.volumes.end() ? &r->second : nullptr;
}

}  // namespace

void judge_conservative_mode(Report& rep, const StageSet& reference, const StageSet& test, const Scene* scene,
                             size_t worst_n) {
  if (test.facts.conservative_mode.empty()) return;
  const ConservativeBound bound = conservative_bound(test.facts, test.root.empty() ? "test set" : test.root);
  auto it = std::find_if(rep.stages.begin(), rep.stages.end(),
                         [](const StageVerdict& v) { return v.stage == st::kVoxelOccupancy; });
  if (it == rep.stages.end()) return;  // no voxels on one side: the report already says so
  const auto vz = reference.settings.is_object() ? reference.settings.find("voxelizer") : reference.settings.end();
  const Volume *e = surface_volume(reference), *t = surface_volume(test);
  StageVerdict v;
  if (vz == reference.settings.end() || *vz != "conservative" || !e || !t) {
    v.stage = st::kVoxelOccupancy;
    v.model = "conservative-superset";
    v.verdict = Verdict::Fail;
    v.note = "the test ran conservative_raster = " + bound.mode +
             ": the reference must voxelize exactly (settings voxelizer = conservative) and both sides hold voxels";
  } else {
    const int n = e->nx;
    v = judge_conservative_occupancy(*e, *t, scene ? voxel_space_triangles(*scene, n) : std::vector<VoxelTriangle>{},
                                     bound, worst_n);
  }
  *it = std::move(v);
}

}  // namespace vct::cmp
