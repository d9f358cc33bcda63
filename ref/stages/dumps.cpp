#include "stages/dumps.h"

#include <algorithm>
#include <string>

namespace vct {

namespace {

// Lowest depth below the clear value 1, so a preview stretches the used range (perspective
// depth crowds near 1); 0 when nothing was drawn.
float lowest_drawn_depth(const Image& depth) {
  float lo = 1.0f;
  for (float v : depth.data)
    if (v < 1.0f) lo = std::min(lo, v);
  return lo >= 1.0f ? 0.0f : lo;
}

// The base level: iso[0] when mips were built (it is the level the marcher sampled), else the
// reduction's output.
const Volume* base_level(const FrameResult& f) {
  if (!f.mips.iso.empty()) return f.mips.iso[0].data.empty() ? nullptr : &f.mips.iso[0];
  return f.voxels.radiance.data.empty() ? nullptr : &f.voxels.radiance;
}

// voxel.occupancy is derived: a voxel is occupied when a fragment landed in it.
Volume occupancy_of(const Volume& fragments) {
  Volume occ(fragments.nx, fragments.ny, fragments.nz, 1);
  occ.channel_names = {"occupancy"};
  for (size_t i = 0; i < occ.data.size(); ++i) occ.data[i] = fragments.data[i] > 0.0f ? 1.0f : 0.0f;
  return occ;
}

const Volume* dumped_volume(const FrameResult& f, const StageRow& row, int index, Volume& scratch) {
  const std::string name = row.name;
  if (name == stage_names::kVoxelRadiance) return base_level(f);
  if (name == stage_names::kVoxelOccupancy) {
    if (f.voxels.fragments.data.empty()) return nullptr;
    scratch = occupancy_of(f.voxels.fragments);
    return &scratch;
  }
  return frame_volume(f, row, index);
}

void write_volume_members(RunDir& dir, const FrameResult& f, const StageRow& row, const Scene& scene) {
  const std::vector<int> members = row.index == StageIndex::None ? std::vector<int>{0} : frame_members(f, row);
  for (int i : members) {
    Volume scratch;
    const Volume* v = dumped_volume(f, row, i, scratch);
    if (!v) continue;
    dir.write_volume(dump_stem(row, i), *v, scene.volume.size / float(v->nx));
  }
}

}  // namespace

void write_stage_image(RunDir& dir, const std::string& stem, const StageRow& row, const Image& img, float position_lo,
                       float position_hi) {
  switch (row.preview) {
    case Preview::Color: dir.write_color(stem, img); return;
    case Preview::Unit: dir.write_data(stem, img, 0.0f, 1.0f); return;
    case Preview::Signed: dir.write_data(stem, img, -1.0f, 1.0f); return;
    case Preview::Depth: dir.write_data(stem, img, lowest_drawn_depth(img), 1.0f); return;
    case Preview::Position: dir.write_data(stem, img, position_lo, position_hi); return;
    case Preview::Volume: break;
  }
  dir.write_data(stem, img, 0.0f, 1.0f);
}

void write_frame_dumps(RunDir& dir, const FrameResult& frame, const Scene& scene) {
  const float lo = std::min({scene.bounds.lo.x, scene.bounds.lo.y, scene.bounds.lo.z});
  const float hi = std::max({scene.bounds.hi.x, scene.bounds.hi.y, scene.bounds.hi.z});
  for (const StageRow& row : stage_rows()) {
    if (*row.dump_stem == '\0') continue;
    if (row.kind == StageKind::Volume) {
      write_volume_members(dir, frame, row, scene);
      continue;
    }
    for (int i : frame_members(frame, row)) write_stage_image(dir, dump_stem(row, i), row, *frame_image(frame, row, i), lo, hi);
  }
  for (const auto& [stage, ms] : frame.timings_ms) dir.add_timing(frame.backend, stage, ms);
  for (const auto& [key, value] : frame.info) dir.json()["info"][frame.backend][key] = value;
  if (!frame.multibounce_energy.empty()) dir.json()["multibounce_energy"][frame.backend] = frame.multibounce_energy;
  dir.save();
}

}  // namespace vct
