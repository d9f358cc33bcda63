// A cluster task's share of a path-traced render: the per-pixel sums of samples [first, end)
// only, accumulated from zero in sample order, with the rays they took. Partial sums of fixed
// sample ranges, added in range order, give the same bytes whoever rendered them, in whatever
// order they finished and however often a task was retried (docs/cluster.md, "Bit-exact merge").
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "pt/accumulator.h"
#include "pt/checkpoint.h"
#include "pt/integrator.h"

namespace vct::pt {

constexpr const char* kPartialSumsMagic = "VCTPTPS1";

struct PartialSums {
  CheckpointKey key;
  uint32_t first_sample = 0;  // sample indices first_sample .. end_sample-1
  uint32_t end_sample = 0;
  RayCounts rays;             // rays these samples traced
  Accumulator sums;           // sums of those samples only; sums.samples() == end_sample
};

/// Writes the file atomically (layout: docs/cluster.md).
void save_partial_sums(const std::string& path, const PartialSums& p);
/// Reads a partial-sums file; InputError(path, what is wrong) when it is not one or is cut short.
PartialSums load_partial_sums(const std::string& path);

/// Adds the partials in ascending first_sample order (the first one copied, the others added
/// per element): they must share `key` and the image size and cover 0 .. spp-1 without gap or
/// overlap, else InputError naming the file that breaks it. The result holds spp samples.
Accumulator merge_partial_sums(std::vector<PartialSums> partials, const CheckpointKey& key, int width, int height,
                               uint32_t spp, RayCounts& rays);

}  // namespace vct::pt
