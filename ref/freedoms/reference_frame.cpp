#include "freedoms/reference_frame.h"

#include "freedoms/reference_freedoms.h"
#include "stages/pipeline.h"

namespace vct {

FrameResult render_ref_frame(const Scene& scene, const Settings& settings) {
  return render_ref_frame(scene, settings, {});
}

FrameResult render_ref_frame(const Scene& scene, const Settings& settings, const std::vector<vec2>& sample_positions) {
  VctFrame frame = run_vct_frame(scene, settings, sample_positions);
  add_reference_freedoms(scene, settings.vct, frame);
  auto& t = frame.result.timings_ms;
  t["total"] = t["total_vct"] + t["total_oracle"];
  return std::move(frame.result);
}

}  // namespace vct
