// The stage registry: names resolve to their rows and family members, every row's slot reaches
// the FrameResult field it names, and the rows keep the pipeline order the verdicts rely on.
#include "stages/stage_registry.h"

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

#include <gtest/gtest.h>

namespace vct {
namespace {

TEST(StageRegistry, FamilyMembersParseAndPrintTheSameName) {
  const auto sm = find_stage("shadow_map.3");
  ASSERT_TRUE(sm);
  EXPECT_STREQ(sm->row->name, "shadow_map");
  EXPECT_EQ(sm->index, 3);
  EXPECT_EQ(stage_name(*sm->row, sm->index), "shadow_map.3");
  const auto mip = find_stage("mip.negz.5");
  ASSERT_TRUE(mip);
  EXPECT_EQ(aniso_direction(*mip->row), int(kNegZ));
  EXPECT_EQ(dump_stem(*mip->row, 5), "aniso_negz_L5");
  EXPECT_EQ(dump_stem(*find_stage("mip.iso.2")->row, 2), "voxels_radiance_L2");
}

TEST(StageRegistry, CubeFacesAreNumberedByLightAndFaceAndNamedInDumps) {
  const auto cube = find_stage("shadow_map_cube.7");  // light 1, face 1 (-x)
  ASSERT_TRUE(cube);
  EXPECT_STREQ(cube->row->name, "shadow_map_cube");
  EXPECT_EQ(cube->index, 7);
  EXPECT_EQ(stage_name(*cube->row, 7), "shadow_map_cube.7");
  EXPECT_EQ(dump_stem(*cube->row, 7), "shadow_map_cube_1_negx");
  EXPECT_EQ(dump_stem(*cube->row, 0), "shadow_map_cube_0_posx");
  EXPECT_EQ(dump_stem(*cube->row, 17), "shadow_map_cube_2_negz");
  EXPECT_EQ(namespace_kind("shadow_map_cube.3"), StageKind::Image);
  // The slot is light i / 6's face i % 6; a spot's entry holds no faces, so it has no members.
  FrameResult f;
  *cube->row->image(f, 9, true) = Image(4, 4, 1);
  ASSERT_EQ(f.shadow_maps.size(), 2u);
  EXPECT_EQ(f.shadow_maps[1].cube[3].width, 4);
  EXPECT_EQ(frame_members(f, *cube->row), (std::vector<int>{9}));
  EXPECT_TRUE(frame_members(f, stage_row(stage_names::kShadowMap)).empty());
}

TEST(StageRegistry, RefusesNamesThatAreNotMembers) {
  EXPECT_FALSE(find_stage("mip.iso.0"));   // level 0 is voxel.radiance
  EXPECT_FALSE(find_stage("mip.iso.x"));
  EXPECT_FALSE(find_stage("mip.iso. 1"));
  EXPECT_FALSE(find_stage("shadow_map"));  // a family needs its index
  EXPECT_FALSE(find_stage("gbuffer.nope"));
  EXPECT_EQ(namespace_kind("gbuffer.nope"), StageKind::Image);  // still an image by namespace
  EXPECT_EQ(namespace_kind("mip.whatever.1"), StageKind::Volume);
  EXPECT_FALSE(namespace_kind("final"));
}

TEST(StageRegistry, SlotsReachTheFieldsTheyName) {
  FrameResult f;
  *find_stage("gbuffer.normal")->row->image(f, 0, true) = Image(2, 2, 3);
  EXPECT_EQ(f.gbuffer.normal.width, 2);
  *find_stage("shadow_map.1")->row->image(f, 1, true) = Image(4, 4, 1);
  ASSERT_EQ(f.shadow_maps.size(), 2u);
  EXPECT_EQ(f.shadow_maps[1].depth.width, 4);
  *find_stage("mip.posy.2")->row->volume(f, 2, true) = Volume(8, 8, 8, 4);
  ASSERT_EQ(f.mips.aniso[kPosY].size(), 2u);  // aniso[d][0] is level 1
  EXPECT_EQ(f.mips.aniso[kPosY][1].nx, 8);
  *find_stage("mip.iso.1")->row->volume(f, 1, true) = Volume(2, 2, 2, 4);
  ASSERT_EQ(f.mips.iso.size(), 2u);  // iso[0] is the base level
  EXPECT_EQ(f.mips.iso[1].nx, 2);
  // Members present: only what holds data.
  EXPECT_EQ(frame_members(f, stage_row(stage_names::kShadowMap)), (std::vector<int>{1}));
  EXPECT_EQ(frame_members(f, mip_row(kPosY)), (std::vector<int>{2}));
  EXPECT_TRUE(frame_members(f, stage_row(stage_names::kGbufferAlbedo)).empty());
}

TEST(StageRegistry, NamesAreUniqueAndFamiliesNumbered) {
  std::set<std::string> names;
  for (const StageRow& row : stage_rows()) {
    EXPECT_TRUE(names.insert(row.name).second) << row.name;
    const bool family = row.index != StageIndex::None;
    // A dumped family's stem names its member; rows without a stem (the reference-only ranges)
    // reach the dumps through the manifest's stage set, named by stage (compare/dump_manifest.h).
    if (*row.dump_stem != '\0') {
      EXPECT_EQ(family, std::string(row.dump_stem).find("{}") != std::string::npos) << row.name;
    }
    EXPECT_TRUE(row.image || row.volume || row.role == StageRole::Derived) << row.name;
    if (row.role != StageRole::Derived) {
      EXPECT_EQ(row.kind == StageKind::Image, row.image != nullptr) << row.name;
    }
  }
}

TEST(StageRegistry, PipelineOrderPutsCausesBeforeEffects) {
  auto pos = [](const char* name) {
    const auto& rows = stage_rows();
    for (size_t i = 0; i < rows.size(); ++i)
      if (std::string(rows[i].name) == name) return i;
    return rows.size();
  };
  EXPECT_LT(pos("shadow_map"), pos("voxel.radiance"));
  EXPECT_LT(pos("gbuffer.normal"), pos("image.direct"));
  EXPECT_LT(pos("voxel.occupancy"), pos("voxel.radiance"));
  EXPECT_LT(pos("voxel.radiance"), pos("mip.iso"));
  EXPECT_LT(pos("mip.negz"), pos("image.indirect_diffuse"));
  EXPECT_LT(pos("image.indirect_diffuse"), pos("image.final"));
}

// Readers follow the registry's pointers (the report's first screen prints them): every docs
// section is a heading of docs/pipeline.md and every source file exists.
TEST(StageRegistry, PointersLeadToTheRepository) {
  std::ifstream in(std::string(VCT_SOURCE_DIR) + "/docs/pipeline.md");
  std::stringstream doc;
  doc << in.rdbuf();
  for (const StageRow& row : stage_rows()) {
    EXPECT_NE(doc.str().find(std::string("### ") + row.docs_section), std::string::npos)
        << row.name << ": no heading '" << row.docs_section << "' in docs/pipeline.md";
    for (const char* sources : {row.ref_source, row.gl_source}) {
      // "a.cpp (fn), b.frag" -> a.cpp, b.frag; "-" = none on that side.
      const std::string list = std::regex_replace(sources, std::regex(" \\([^)]*\\)"), "");
      std::stringstream items(list);
      for (std::string path; std::getline(items, path, ',');) {
        path.erase(0, path.find_first_not_of(' '));
        if (path == "-") continue;
        EXPECT_TRUE(std::filesystem::exists(std::string(VCT_SOURCE_DIR) + "/" + path)) << row.name << ": " << path;
      }
    }
    EXPECT_GT(std::string(row.what).size(), 0u) << row.name;
  }
}

}  // namespace
}  // namespace vct
