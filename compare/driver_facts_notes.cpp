#include "compare/driver_facts_notes.h"

#include <string>

#include "stages/stage_registry.h"

namespace vct::cmp {
namespace {

bool starts(const std::string& s, const char* prefix) { return s.rfind(prefix, 0) == 0; }

ToleranceModel model_of(const std::string& stage) {
  const auto ref = find_stage(stage);
  return ref ? ref->row->model : ToleranceModel::None;
}

// Stages decided by the voxelization raster (sample positions, sub-pixel snapping).
bool voxel_raster_stage(const std::string& stage) {
  const ToleranceModel m = model_of(stage);
  return m == ToleranceModel::VoxelOccupancy || m == ToleranceModel::VoxelRadiance || m == ToleranceModel::VoxelHoles;
}
// Stages decided by the camera or light raster (sub-pixel snapping of edges): the G-buffer and
// shadow maps, i.e. every stage judged by a raster model.
bool camera_raster_stage(const std::string& stage) {
  const ToleranceModel m = model_of(stage);
  return m == ToleranceModel::Depth || m == ToleranceModel::Coverage || m == ToleranceModel::Position ||
         m == ToleranceModel::NormalMap || m == ToleranceModel::Texture;
}
// Stages whose bounds assume the texture filter's sub-texel precision.
bool texture_stage(const std::string& stage) {
  const ToleranceModel m = model_of(stage);
  return m == ToleranceModel::Texture || m == ToleranceModel::NormalMap;
}

void append(StageVerdict& v, const std::string& sentence) {
  v.note += (v.note.empty() ? "" : " ") + sentence;
}

std::string positions_text(const std::vector<vec2>& p) {
  std::string s;
  for (const vec2& v : p) s += (s.empty() ? "" : " ") + std::to_string(v.x).substr(0, 6) + "," + std::to_string(v.y).substr(0, 6);
  return s;
}

}  // namespace

void note_driver_facts(Report& rep, const BackendFacts& test, const BackendFacts& reference) {
  if (test.empty()) return;  // an external set without facts: nothing known, nothing claimed
  const bool mirrored = !test.sample_positions.empty() && test.sample_positions == reference.sample_positions;
  const bool positions_unknown = test.sample_positions.empty();
  const bool subpixel_differs = test.subpixel_bits > 0 && test.subpixel_bits != cpu_subpixel_bits();
  for (StageVerdict& v : rep.stages) {
    if (voxel_raster_stage(v.stage)) {
      if (positions_unknown)
        append(v, "Driver fact not reported: GL_SAMPLE_POSITION (the CPU assumed the standard pattern).");
      else if (!mirrored && !reference.sample_positions.empty())
        append(v, "The CPU sampled at " + positions_text(reference.sample_positions) + ", the driver at " +
                      positions_text(test.sample_positions) + ": occupancy may differ for that reason.");
    }
    if ((voxel_raster_stage(v.stage) || camera_raster_stage(v.stage)) && subpixel_differs)
      append(v, "The driver snaps to 2^-" + std::to_string(test.subpixel_bits) + " pixel (GL_SUBPIXEL_BITS), the CPU to 2^-" +
                    std::to_string(cpu_subpixel_bits()) + ": edge coverage may differ for that reason.");
    if ((voxel_raster_stage(v.stage) || camera_raster_stage(v.stage)) && test.subpixel_bits < 0)
      append(v, "Driver fact not reported: GL_SUBPIXEL_BITS.");
    if (texture_stage(v.stage))
      for (const std::string& u : test.unreported)
        if (starts(u, "texture filtering")) append(v, "Driver fact not reported: " + u.substr(0, u.find(':')) + " (bounds assume 8 bits).");
  }
}

}  // namespace vct::cmp
