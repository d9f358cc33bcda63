#include "compare/dump_manifest.h"

#include <filesystem>

#include "compare/stage_set.h"
#include "io/atomic_file.h"
#include "stages/stage_registry.h"

namespace vct::cmp {

namespace {

// ref/stages/dumps.cpp writes every member of a row with a dump stem from the frame's own slot,
// except two volumes: voxel.radiance is dumped as the base level the marcher sampled (mip.iso
// level 0 once mips are built, which multibounce can make differ from the reduction's output the
// stage set holds), and voxel.occupancy is derived there from the fragment counts.
bool dump_holds_the_stage(const StageRow& row) {
  if (*row.dump_stem == '\0') return false;
  const std::string name = row.name;
  return name != stage_names::kVoxelRadiance && name != stage_names::kVoxelOccupancy;
}

nlohmann::json entry(const std::string& file_stem, StageKind kind) {
  const bool image = kind == StageKind::Image;
  return {{"file", file_stem + (image ? ".exr" : ".nrrd")}, {"kind", image ? "image" : "volume"},
          {"preview", file_stem + ".png"}};
}

}  // namespace

void write_dump_manifest(const std::string& dir, const FrameResult& f, const VctSettings& s) {
  StageSet header = stage_set_header(f, s);
  StageSet undumped = header;
  nlohmann::json stages = nlohmann::json::object();
  for (const StageRow& row : stage_rows())
    for (int i : frame_members(f, row)) {
      if (dump_holds_the_stage(row)) {
        stages[stage_name(row, i)] = entry(dump_stem(row, i), row.kind);
      } else if (row.kind == StageKind::Image) {
        undumped.images[stage_name(row, i)] = *frame_image(f, row, i);
      } else {
        undumped.volumes[stage_name(row, i)] = *frame_volume(f, row, i);
      }
    }
  if (!undumped.images.empty() || !undumped.volumes.empty()) {
    write_stage_set((std::filesystem::path(dir) / kUndumpedStagesDir).string(), undumped);
    const std::string prefix = std::string(kUndumpedStagesDir) + "/";
    for (const auto& [name, file] : undumped.files) {
      const std::string stem = file.substr(0, file.rfind('.'));
      stages[name] = entry(prefix + stem, undumped.images.count(name) ? StageKind::Image : StageKind::Volume);
    }
  }
  write_text_atomically((std::filesystem::path(dir) / "vct-stages.json").string(),
                        stage_set_manifest(header, stages).dump(2) + "\n");
}

}  // namespace vct::cmp
