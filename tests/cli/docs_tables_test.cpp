// The docs' settings and stage tables are the tables' own output (`vct settings --markdown`,
// `vct stages --markdown`): a row added to the code without the docs, or docs edited by hand,
// fail here.
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "compare/admission.h"
#include "compare/counted_shares.h"
#include "core/precision.h"
#include "core/settings_table.h"
#include "stages/stage_registry_text.h"

namespace {

std::string read_doc(const std::string& name) {
  std::ifstream in(std::string(VCT_SOURCE_DIR) + "/docs/" + name);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

TEST(DocsTables, SettingsMdHoldsTheSettingsTable) {
  const std::string doc = read_doc("settings.md");
  ASSERT_FALSE(doc.empty());
  EXPECT_NE(doc.find(vct::settings_markdown()), std::string::npos)
      << "docs/settings.md is out of date: regenerate its table with `vct settings --markdown`";
}

TEST(DocsTables, ExternalFormatHoldsTheStageRegistry) {
  const std::string doc = read_doc("external_format.md");
  ASSERT_FALSE(doc.empty());
  EXPECT_NE(doc.find(vct::stage_registry_markdown()), std::string::npos)
      << "docs/external_format.md is out of date: regenerate its registry table with `vct stages --markdown`";
}

TEST(DocsTables, CompareMdHoldsTheAdmissionTableAndCountedShares) {
  const std::string doc = read_doc("compare.md");
  ASSERT_FALSE(doc.empty());
  EXPECT_NE(doc.find(vct::cmp::admission_table_markdown()), std::string::npos)
      << "docs/compare.md is out of date: regenerate its admission table with `vct stages --rules`";
  EXPECT_NE(doc.find(vct::cmp::counted_shares_markdown()), std::string::npos)
      << "docs/compare.md is out of date: regenerate its counted shares with `vct stages --rules`";
}

TEST(DocsTables, CompareMdHoldsThePrecisionTable) {
  const std::string doc = read_doc("compare.md");
  ASSERT_FALSE(doc.empty());
  EXPECT_NE(doc.find(vct::precision_table_markdown()), std::string::npos)
      << "docs/compare.md is out of date: regenerate its precision table with `vct stages --rules`";
}

TEST(DocsTables, EveryVctSettingHasARowAndRoundTrips) {
  // The JSON written from the table reads back through the table to the same JSON.
  vct::Settings s;
  s.vct.grid = 32;
  s.vct.anisotropic = true;
  s.vct.reduction = vct::Reduction::CasRgba8;
  s.pt.spp = 7;
  const nlohmann::json j = s;
  EXPECT_EQ(j["vct"].size(), vct::vct_setting_fields().size());
  EXPECT_EQ(j["pt"].size(), vct::pt_setting_fields().size());
  const vct::Settings back = j.get<vct::Settings>();
  EXPECT_EQ(nlohmann::json(back), j);
  EXPECT_EQ(j["vct"]["reduction"], "cas");
}

}  // namespace
