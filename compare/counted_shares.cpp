#include "compare/counted_shares.h"

#include <cstdio>

namespace vct::cmp {

std::string counted_shares_markdown() {
  std::string md = "| share | cap | of | why a count |\n| --- | --- | --- | --- |\n";
  for (const CountedShare* s : kCountedShares) {
    char cap[32];
    std::snprintf(cap, sizeof cap, "%.3g %%", 100.0 * s->fraction);
    md += "| " + std::string(s->name) + " | " + cap + " | " + s->denominator + " | " + s->why_a_count + " |\n";
  }
  return md;
}

}  // namespace vct::cmp
