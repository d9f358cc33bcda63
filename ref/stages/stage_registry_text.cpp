#include "stages/stage_registry_text.h"

#include <sstream>

#include "stages/stage_registry.h"

namespace vct {

namespace {

const char* kind_name(StageKind k) { return k == StageKind::Image ? "image" : "volume"; }

const char* index_name(StageIndex i) {
  switch (i) {
    case StageIndex::None: return nullptr;
    case StageIndex::Light: return "light";
    case StageIndex::MipLevel: return "mip_level";
    case StageIndex::CubeFace: return "cube_face";
    case StageIndex::Frame: return "frame";
  }
  return nullptr;
}

const char* role_name(StageRole r) {
  switch (r) {
    case StageRole::Judged: return "judged";
    case StageRole::Auxiliary: return "auxiliary";
    case StageRole::Derived: return "derived";
  }
  return "judged";
}

const char* model_name(ToleranceModel m) {
  switch (m) {
    case ToleranceModel::None: return "none";
    case ToleranceModel::Depth: return "depth";
    case ToleranceModel::Coverage: return "coverage";
    case ToleranceModel::Position: return "position";
    case ToleranceModel::NormalMap: return "normal_map";
    case ToleranceModel::Texture: return "texture";
    case ToleranceModel::Shading: return "shading";
    case ToleranceModel::ConeVisibility: return "cone_visibility";
    case ToleranceModel::Filtered: return "filtered";
    case ToleranceModel::VoxelOccupancy: return "voxel_occupancy";
    case ToleranceModel::VoxelRadiance: return "voxel_radiance";
    case ToleranceModel::VoxelFrame: return "voxel_frame";
    case ToleranceModel::VoxelEnergy: return "voxel_energy";
    case ToleranceModel::VoxelHoles: return "voxel_holes";
    case ToleranceModel::Mip: return "mip";
  }
  return "none";
}

const char* cone_input_name(ConeInput c) {
  switch (c) {
    case ConeInput::No: return "no";
    case ConeInput::Always: return "always";
    case ConeInput::UnlessSoftShadows: return "unless soft shadows";
    case ConeInput::WithParticles: return "with particles";
    case ConeInput::ChosenMips: return "the chosen mip chain";
  }
  return "no";
}

// How a family's members are spelled in the docs: "shadow_map.<light>", "mip.iso.<level>".
std::string display_name(const StageRow& row) {
  switch (row.index) {
    case StageIndex::None: return row.name;
    case StageIndex::Light: return std::string(row.name) + ".<light>";
    case StageIndex::MipLevel: return std::string(row.name) + ".<level>";
    case StageIndex::CubeFace: return std::string(row.name) + ".<light x 6 + face>";
    case StageIndex::Frame: return std::string(row.name) + ".<frame>";
  }
  return row.name;
}

std::string display_stem(const StageRow& row) {
  std::string s = row.dump_stem;
  const size_t at = s.find("{}");
  const char* member = row.index == StageIndex::Light      ? "<light>"
                       : row.index == StageIndex::CubeFace ? "<light>_<face>"
                       : row.index == StageIndex::Frame    ? "<frame>"
                                                           : "<level>";
  if (at != std::string::npos) s.replace(at, 2, member);
  return s;
}

}  // namespace

nlohmann::json stage_registry_json() {
  nlohmann::json rows = nlohmann::json::array();
  for (const StageRow& row : stage_rows()) {
    const char* family = index_name(row.index);
    rows.push_back({{"name", row.name},
                    {"family", family ? nlohmann::json(family) : nlohmann::json(nullptr)},
                    {"kind", kind_name(row.kind)},
                    {"role", role_name(row.role)},
                    {"dump_stem", row.dump_stem},
                    {"tolerance_model", model_name(row.model)},
                    {"own_inputs", row.own_inputs},
                    {"cone_input", cone_input_name(row.cone_input)},
                    {"channels", row.channels},
                    {"pt_aov", row.pt_aov},
                    {"what", row.what},
                    {"docs", std::string("docs/pipeline.md § ") + row.docs_section},
                    {"ref_source", row.ref_source},
                    {"gl_source", row.gl_source},
                    {"walkthrough_step", row.walkthrough_step}});
  }
  return rows;
}

std::string stage_registry_markdown() {
  std::ostringstream o;
  o << "| stage | kind | role | `vct render --dump` file | tolerance model | judged on the test's own inputs | "
       "`--scene` input | path tracer AOV |\n| --- | --- | --- | --- | --- | --- | --- | --- |\n";
  for (const StageRow& row : stage_rows()) {
    const std::string stem = display_stem(row);
    o << "| `" << display_name(row) << "` | " << kind_name(row.kind) << " | " << role_name(row.role) << " | "
      << (stem.empty() ? "-" : "`" + stem + "`") << " | " << model_name(row.model) << " | "
      << (row.own_inputs ? "yes" : "no") << " | " << cone_input_name(row.cone_input) << " | "
      << (*row.pt_aov ? "`" + std::string(row.pt_aov) + "`" : "-") << " |\n";
  }
  return o.str();
}

}  // namespace vct
