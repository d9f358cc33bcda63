// The stage registry: one row per stage a VCT frame produces. Every module that names stages
// reads it: the dump writer (`vct render --dump`), stage sets in both directions (compare/
// stage_set*.cpp), the comparison's order and tolerance models, and the report (validate writes
// the table into run.json; `vct stages --json` prints it). Adding a stage is one row here plus its computation (docs/CONVENTIONS.md).
//
// Families are numbered: "shadow_map.<light>", "shadow_map_cube.<light x 6 + face>" (and their
// reference-only ranges "shadow_map_tie_range.<light>", "shadow_map_cube_tie_range.<light x 6 +
// face>"), "mip.iso.<level>", "mip.<dir>.<level>" (level >= 1).
// Row order is the pipeline order: the first failing stage in this order is the one to blame.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "stages/stage_types.h"

namespace vct {

/// The names code refers to (the rows below hold the rest of each stage's facts). Families are
/// the prefix of their members: stage_name(stage_row(kMipIso), 2) is "mip.iso.2".
namespace stage_names {
inline constexpr char kShadowMap[] = "shadow_map";
inline constexpr char kShadowMapCube[] = "shadow_map_cube";
inline constexpr char kShadowMapTieRange[] = "shadow_map_tie_range";
inline constexpr char kShadowMapCubeTieRange[] = "shadow_map_cube_tie_range";
inline constexpr char kGbufferCoverage[] = "gbuffer.coverage";
inline constexpr char kGbufferDepth[] = "gbuffer.depth";
inline constexpr char kGbufferPosition[] = "gbuffer.position";
inline constexpr char kGbufferNormal[] = "gbuffer.normal";
inline constexpr char kGbufferAlbedo[] = "gbuffer.albedo";
inline constexpr char kGbufferMaterial[] = "gbuffer.material";
inline constexpr char kGbufferSpecularColor[] = "gbuffer.specular_color";
inline constexpr char kGbufferEmission[] = "gbuffer.emission";
inline constexpr char kGbufferTextureSlack[] = "gbuffer.texture_slack";
inline constexpr char kGbufferTieRange[] = "gbuffer.tie_range";
inline constexpr char kImageDirect[] = "image.direct";
inline constexpr char kVoxelOccupancy[] = "voxel.occupancy";
inline constexpr char kVoxelFrame[] = "voxel.frame";
inline constexpr char kVoxelEnergy[] = "voxel.energy";
inline constexpr char kVoxelRadiance[] = "voxel.radiance";
inline constexpr char kVoxelFragments[] = "voxel.fragments";
inline constexpr char kVoxelCasLo[] = "voxel.cas_lo";
inline constexpr char kVoxelCasHi[] = "voxel.cas_hi";
inline constexpr char kVoxelShadingSlack[] = "voxel.shading_slack";
inline constexpr char kVoxelConservative[] = "voxel.conservative";
inline constexpr char kVoxelBounceInput[] = "voxel.bounce_input";
inline constexpr char kVoxelExact[] = "voxel.exact";
inline constexpr char kVoxelOccupancyTie[] = "voxel.occupancy_tie";
inline constexpr char kVoxelFragmentCountRange[] = "voxel.fragment_count_range";
inline constexpr char kVoxelHoles[] = "voxel.holes";
inline constexpr char kMipIso[] = "mip.iso";
inline constexpr char kMipPosx[] = "mip.posx";
inline constexpr char kMipNegx[] = "mip.negx";
inline constexpr char kMipPosy[] = "mip.posy";
inline constexpr char kMipNegy[] = "mip.negy";
inline constexpr char kMipPosz[] = "mip.posz";
inline constexpr char kMipNegz[] = "mip.negz";
inline constexpr char kImageSoftShadow[] = "image.soft_shadow";
inline constexpr char kImageIndirectDiffuse[] = "image.indirect_diffuse";
inline constexpr char kImageIndirectSpecular[] = "image.indirect_specular";
inline constexpr char kImageDiffuseTerm[] = "image.diffuse_term";
inline constexpr char kImageSpecularTerm[] = "image.specular_term";
inline constexpr char kImageEmission[] = "image.emission";
inline constexpr char kImageParticles[] = "image.particles";
inline constexpr char kImageFinal[] = "image.final";
}  // namespace stage_names

enum class StageKind { Image, Volume };

/// How a family's members are numbered (None: a single stage). CubeFace: light x 6 + face, the
/// faces in GL's order (kCubeFaceNames); dump stems spell the member "<light>_<face>".
enum class StageIndex { None, Light, MipLevel, CubeFace, Frame };

/// Judged: compared on its own. Auxiliary: a reference input that other stages' verdicts use
/// (fragment counts, CAS intervals, texture slack). Derived: made by the judge from other stages.
enum class StageRole { Judged, Auxiliary, Derived };

/// How a PNG preview maps the data (the EXR/NRRD beside it always holds the values).
enum class Preview {
  Color,     // tone-mapped linear radiance
  Unit,      // [0, 1] to grey
  Signed,    // [-1, 1] to grey (normals)
  Depth,     // the used depth range up to 1 (perspective depth crowds near 1)
  Position,  // the scene's (or the data's) extent
  Volume,    // slice montage
};

/// The tolerance model a stage is judged by (compare/tolerance.cpp states each bound and its
/// source; docs/compare.md derives them).
enum class ToleranceModel {
  None,               // auxiliary stages
  Depth,              // D32F window depth
  Coverage,           // exact, fill-rule ties
  Position,           // interpolated attribute
  NormalMap,          // 8-bit filtering weights on [-1,1] normal-map texels
  Texture,            // 8-bit sub-texel and LOD weights
  Shading,            // shared BRDF in float on G-buffer inputs
  ConeVisibility,     // cone-traced visibility
  Filtered,           // cone-traced radiance
  VoxelOccupancy,     // same coverage rule, ties
  VoxelRadiance,      // chosen by the test's storage and reduction (voxel_model)
  VoxelFrame,         // a multibounce frame before the last: voxel_radiance on the test's own inputs
  VoxelEnergy,        // the multibounce energy sequence: per frame, the sum of the voxels' bounds
  VoxelHoles,         // reported, never failed
  Mip,                // propagated from the voxel radiance model
};

/// Whether re-tracing the cone stages on a test's own inputs (compare/stage_set_frame.h) reads
/// this stage.
enum class ConeInput {
  No,
  Always,
  UnlessSoftShadows,  // image.direct: soft shadows re-trace it from the mips
  WithParticles,      // image.particles: the composite adds it when the scene has emitters
  ChosenMips,         // the mip chain the settings select (iso, or the six directions)
};

struct StageRow {
  const char* name;       // canonical name, or family prefix ("shadow_map", "mip.iso")
  const char* dump_stem;  // `vct render --dump` file stem; "{}" = the family index; "" = not dumped
  StageKind kind;
  StageIndex index;
  StageRole role;
  Preview preview;
  ToleranceModel model;
  // Judged on the test's own inputs (the cone stages re-traced from the test's G-buffer, direct
  // light and mips: compare/isolated_stages.h), so an upstream tie does not move the blame here.
  bool own_inputs;
  ConeInput cone_input;
  int channels;  // channels the marcher indexes when the stage is a --scene input (0 = any)
  // The path tracer's AOV that measures the same light ("" = none): the bias pairs
  // (compare/bias.h, docs/pathtracer.md).
  const char* pt_aov;
  // The FrameResult slot of member `i` (i = 0 for single stages); grows families on demand when
  // `grow`, else nullptr for a member the frame does not have.
  Image* (*image)(FrameResult& f, int i, bool grow);
  Volume* (*volume)(FrameResult& f, int i, bool grow);
  // For readers (docs/external_format.md, the report's first screen and walkthrough): what the
  // stage holds, the docs/pipeline.md section that defines it, the files that compute it on each
  // side ("-" = reference only), and the report walkthrough step that shows it ("" = none).
  const char* what;
  const char* docs_section;
  const char* ref_source;
  const char* gl_source;
  const char* walkthrough_step;
};

/// Every row, in pipeline order.
const std::vector<StageRow>& stage_rows();

/// A stage name resolved to its row (and family member).
struct StageRef {
  const StageRow* row = nullptr;
  int index = 0;  // light or mip level; 0 for single stages
};

/// "mip.posx.3" -> {row mip.posx, 3}; nullopt for names not in the registry (a level 0 or a
/// non-number suffix is not a member either).
std::optional<StageRef> find_stage(const std::string& name);

/// The kind every stage of a name's namespace has ("gbuffer.*", "image.*", "shadow_map.*" are
/// images; "voxel.*", "mip.*" volumes), also for names the registry does not list; nullopt
/// outside those namespaces.
std::optional<StageKind> namespace_kind(const std::string& name);

/// The row of a single stage by name; throws std::logic_error for a name not in the table (a
/// programming error: callers pass the registry's own names).
const StageRow& stage_row(const std::string& name);

/// Canonical name of a family member ("shadow_map", 2 -> "shadow_map.2") or the single name.
std::string stage_name(const StageRow& row, int index = 0);
/// Dump file stem of a member ("voxels_radiance_L{}", 3 -> "voxels_radiance_L3"; a cube face
/// names its light and face: "shadow_map_cube_{}", 7 -> "shadow_map_cube_1_negx").
std::string dump_stem(const StageRow& row, int index = 0);

/// The mip chain row of an anisotropic direction (AnisoDir), or the isotropic chain for -1.
const StageRow& mip_row(int direction);

/// The anisotropic direction a "mip.<dir>" row stands for (-1 for the isotropic chain and
/// every other row).
int aniso_direction(const StageRow& row);

/// Whether the judge re-traces this stage on the test's own inputs: the cone stages always, and
/// direct light when soft shadows trace it through the mips (then it is ordered after them too).
bool judged_on_own_inputs(const StageRow& row, bool soft_shadows);

/// A frame's stage slot for reading: nullptr if the frame has no such member or it is empty.
const Image* frame_image(const FrameResult& f, const StageRow& row, int index = 0);
const Volume* frame_volume(const FrameResult& f, const StageRow& row, int index = 0);

/// Members present in a frame: for single stages {0} if filled, for families every index held.
std::vector<int> frame_members(const FrameResult& f, const StageRow& row);

}  // namespace vct
