// Debug labels (glObjectLabel, GL 4.5 §20.9) on the frame's stage textures, so a frame debugger
// names them and a capture map can point at them (docs/external_format.md, "From a RenderDoc
// capture": the labels are the `resource` names of our own map, tools/import_capture/vct_gl_map.json).
#pragma once

namespace vct::gl {

struct GlFrame;

/// Labels every texture a stage is read back from: "vct.shadow_maps", "vct.gbuffer.position", ...
void label_frame_textures(const GlFrame& f);

}  // namespace vct::gl
