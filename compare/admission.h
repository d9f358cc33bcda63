// The admission table: every way an element (pixel, texel, voxel) of a compared stage may pass,
// one row per (stage family, rule), in the order the judge tries them (dEQP's verifiers are the
// model: a tolerance is a small set of precisions, validity a per-element predicate, counting policy
// apart). Each judged element records the first rule that admitted it, so a verdict says why it
// passed (StageVerdict::admitted_by) and every mask paints the same rule in the same colour.
// docs/compare.md, "Admission rules", is generated from this table (`vct stages --rules`) and
// checked by a test. Adding a rule: one row here plus its predicate (docs/CONVENTIONS.md).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

#include "core/math.h"

namespace vct::cmp {

/// Stage families: the elements one judge function walks.
enum class Family : uint8_t { Image, Volume, Occupancy, Radiance, Cones };

/// What a rule is: a term of the element's bound, a range of admissible values the reference
/// computed, a neighbourhood predicate, a counted share (a cap on how many elements, not a value),
/// or a re-judgement of the stage on other inputs.
enum class RuleKind : uint8_t { Bound, Range, Neighbour, CountedShare, Rejudge };

/// Every admission rule. Beyond = admitted by none (the element fails); always first.
enum class Rule : uint8_t {
  Beyond,
  WithinBound,
  RasterAlternative,
  LightSpaceAlternative,
  PcfTapRange,
  EdgeNeighbour,
  EdgeShare,
  InteriorShare,
  UpstreamShare,
  VolumeWithinBound,
  AboveUpstreamTie,
  CoverageTie,
  FaceNeighbourTie,
  EdgeFragmentsTie,
  FillRay,
  ConservativeHole,
  RadianceWithinBound,
  ShadingShare,
  EnergyWithinBound,
  OwnInputs,
  MarchEnd,
  kCount
};
inline constexpr size_t kRuleCount = size_t(Rule::kCount);

struct AdmissionRow {
  Rule rule;
  const char* name;         // as written in run.json's admitted_by and the legends
  Family family;
  RuleKind kind;
  const char* reads;        // the auxiliary stage and channel it reads ("" = only the two values)
  const char* constant;     // its constant, in words
  const char* denominator;  // counted shares: what the share is a share of ("" = any count)
  const char* doc;          // the docs/compare.md section deriving it
  std::array<uint8_t, 3> colour;  // in every mask (red is reserved for Beyond)
};

/// The table, in Rule order.
const std::array<AdmissionRow, kRuleCount>& admission_table();
const AdmissionRow& admission_row(Rule r);
inline std::string rule_name(Rule r) { return admission_row(r).name; }
std::string to_string(Family f);
std::string to_string(RuleKind k);

/// docs/compare.md's "Admission rules" table (Markdown), written from admission_table().
std::string admission_table_markdown();

/// How many elements each rule admitted (and how many none did), for one stage.
struct RuleTally {
  std::array<size_t, kRuleCount> count{};
  void add(Rule r, size_t n = 1) { count[size_t(r)] += n; }
  size_t operator[](Rule r) const { return count[size_t(r)]; }
  /// {rule name: count} for every rule with a non-zero count (run.json's admitted_by).
  nlohmann::json json() const;
};

/// Rules that admit an element within its bound (not a freedom beyond it).
bool within_bound_rule(Rule r);

}  // namespace vct::cmp
