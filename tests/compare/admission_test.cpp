// The admission table (compare/admission.h): its rows, and the rule each judge records per element
// on hand-made cases whose rule is known.
#include <fstream>
#include <set>
#include <sstream>

#include <gtest/gtest.h>

#include "compare/admission.h"
#include "compare/stage_compare.h"
#include "find_verdict.h"

namespace vct::cmp {
namespace {

using test::find;

std::string compare_md() {
  std::ifstream in(std::string(VCT_SOURCE_DIR) + "/docs/compare.md");
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

TEST(Admission, RowsAreInRuleOrderWithUniqueNamesAndDerivedInAnExistingSection) {
  const std::string doc = compare_md();
  ASSERT_FALSE(doc.empty());
  std::set<std::string> names;
  for (size_t i = 0; i < kRuleCount; ++i) {
    const AdmissionRow& row = admission_table()[i];
    EXPECT_EQ(size_t(row.rule), i);
    EXPECT_TRUE(names.insert(row.name).second) << row.name;
    // Every row cites a heading of docs/compare.md that derives it.
    EXPECT_NE(doc.find("# " + std::string(row.doc) + "\n"), std::string::npos) << row.name << ": " << row.doc;
    // Failures are red and nothing else is.
    const bool red = row.colour == std::array<uint8_t, 3>{255, 0, 0};
    EXPECT_EQ(red, row.rule == Rule::Beyond) << row.name;
    // A counted share names what it is a share of.
    if (row.kind == RuleKind::CountedShare) {
      EXPECT_STRNE(row.denominator, "") << row.name;
    }
  }
}

// A w x h single-channel image of `value`.
Image flat(int w, int h, float value) {
  Image im(w, h, 1);
  for (float& x : im.data) x = value;
  return im;
}

TEST(Admission, AnInteriorValueOutsideItsNeighbourhoodIsAdmittedByNoRule) {
  // image.final (filtered-8bit): bound at 1.0 is 1e-6 + 2^-5 + 2^-8 mean = 0.0352; 1.5 is beyond it
  // and beyond the flat 3x3 range plus the bound.
  const Image ref = flat(100, 100, 1.0f);
  Image test = ref;
  test.at(50, 50, 0) = 1.5f;
  const StageVerdict v = compare_image_stage("image.final", ref, test, nullptr, {});
  EXPECT_EQ(v.verdict, Verdict::Fail);
  EXPECT_EQ(v.admitted[Rule::Beyond], 1u);
  EXPECT_EQ(v.admitted[Rule::WithinBound], 9999u);
  EXPECT_EQ(v.admitted.json(), (nlohmann::json{{"beyond", 1}, {"within-bound", 9999}}));
}

TEST(Admission, AShadingStagesInteriorPixelIsACountedShare) {
  // image.direct (shading-float) skips the neighbour predicate: 1 pixel of 10^4 = 0.01 % <= 0.1 %.
  const Image ref = flat(100, 100, 1.0f);
  Image test = ref;
  test.at(50, 50, 0) = 1.5f;
  StageVerdict v = compare_image_stage("image.direct", ref, test, nullptr, {});
  EXPECT_EQ(v.verdict, Verdict::Warn);
  EXPECT_EQ(v.admitted[Rule::InteriorShare], 1u);
  // 20 such pixels are 0.2 % > 0.1 %: the share is exceeded, and its pixels are failures, not admitted.
  for (int i = 0; i < 20; ++i) test.at(10 + 4 * i, 20, 0) = 1.5f;
  v = compare_image_stage("image.direct", ref, test, nullptr, {});
  EXPECT_EQ(v.verdict, Verdict::Fail);
  EXPECT_EQ(v.admitted[Rule::InteriorShare], 0u);
  EXPECT_EQ(v.admitted[Rule::Beyond], 21u);
  EXPECT_EQ(v.allowed, 21u);  // counted as tolerated before the share decided, as the note says
}

TEST(Admission, AnEdgePixelShowingItsNeighboursValueIsAnEdgeNeighbour) {
  // gbuffer.position: a step from 0 to 1 between columns 49 and 50 (the edge map flags both
  // columns); GL shows the right surface one pixel early at one row: a neighbour's value.
  Image ref = flat(100, 100, 0.0f);
  for (int y = 0; y < 100; ++y)
    for (int x = 50; x < 100; ++x) ref.at(x, y, 0) = 1.0f;
  Image test = ref;
  test.at(49, 30, 0) = 1.0f;
  const StageVerdict v = compare_image_stage("gbuffer.position", ref, test, nullptr, {});
  EXPECT_EQ(v.verdict, Verdict::Warn) << v.note;
  EXPECT_EQ(v.admitted[Rule::EdgeNeighbour], 1u);
  EXPECT_EQ(v.admitted[Rule::Beyond], 0u);
}

StageSet floor_set(int z_of_moved) {
  StageSet s;
  s.backend = "test";
  s.storage = "rgba16f";
  s.reduction = "fixed_point";
  Volume v(16, 16, 16, 4);
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) v.set_rgba(x, y, 5, vec4(0.5f, 0.5f, 0.5f, 1.0f));
  if (z_of_moved != 5) {
    v.set_rgba(7, 7, 5, vec4(0.0f));
    v.set_rgba(7, 7, z_of_moved, vec4(0.5f, 0.5f, 0.5f, 1.0f));
  }
  s.volumes["voxel.radiance"] = v;
  return s;
}

TEST(Admission, AVoxelMovedToItsNeighbourIsAFaceNeighbourTieAndAFarOneIsNot) {
  // 256 occupied voxels; a pair of ties is 0.78 % <= 1 %.
  const StageVerdict near = find(compare_stage_sets(floor_set(5), floor_set(6)), "voxel.occupancy");
  EXPECT_EQ(near.verdict, Verdict::Warn);
  EXPECT_EQ(near.admitted[Rule::FaceNeighbourTie], 2u);
  const StageVerdict far = find(compare_stage_sets(floor_set(5), floor_set(9)), "voxel.occupancy");
  EXPECT_EQ(far.verdict, Verdict::Fail);
  EXPECT_EQ(far.admitted[Rule::Beyond], 2u);
}

}  // namespace
}  // namespace vct::cmp
