"""Where to read what a stage computes: for each stage name prefix (docs/external_format.md lists
the names), one line on what it is, the docs/pipeline.md section (its heading), and the source files of the CPU
reference and of the GL build (paths relative to the repository root)."""

# (prefix, what it computes, docs section, reference source, GL source); first match wins.
STAGE_DOCS = [
    ("shadow_map.", "the spot light's D32F depth map", "docs/pipeline.md § Shadow maps",
     "ref/stages/shadow_map.cpp", "gl/gl_pass_raster.cpp (shadow_pass), gl/shaders/depth_only.frag"),
    ("gbuffer.", "the camera G-buffer (per pixel centre: position, normal, material, depth, coverage)",
     "docs/pipeline.md § G-buffer and direct light",
     "ref/stages/gbuffer.cpp, ref/stages/raster.cpp", "gl/gl_pass_raster.cpp (gbuffer_pass), gl/shaders/gbuffer.frag"),
    ("image.direct", "Cook-Torrance direct light with shadow-map visibility",
     "docs/pipeline.md § G-buffer and direct light",
     "ref/stages/direct.cpp", "gl/gl_pass_shading.cpp (direct_pass), gl/shaders/direct.frag"),
    ("voxel.occupancy", "which voxels the voxelizer's coverage rule fills", "docs/pipeline.md § Voxelizers",
     "ref/stages/voxelize_gpu.cpp", "gl/gl_pass_voxel.cpp (voxelize), gl/shaders/voxelize.geom"),
    ("voxel.holes", "voxels the conservative set has and the sample rule misses", "docs/pipeline.md § Voxelizers",
     "ref/stages/voxelize_conservative.cpp", "gl/shaders/voxelize.geom"),
    ("voxel.", "injected voxel radiance (RGB) and opacity (A), averaged per voxel",
     "docs/pipeline.md § Reduction",
     "ref/stages/voxelize.cpp, ref/stages/inject.cpp, ref/stages/reduction.cpp",
     "gl/gl_pass_voxel.cpp (voxelize, resolve), gl/shaders/voxelize.frag, gl/shaders/voxel_resolve.comp"),
    ("mip.iso.", "isotropic 2x2x2 box-filtered mip level", "docs/pipeline.md § Mips",
     "ref/stages/mips.cpp", "gl/gl_pass_voxel.cpp (build_mips), gl/shaders/mip_iso.comp"),
    ("mip.", "anisotropic directional mip level (front-to-back pairs)", "docs/pipeline.md § Mips",
     "ref/stages/mips.cpp", "gl/gl_pass_voxel.cpp (build_mips), gl/shaders/mip_aniso.comp"),
    ("image.indirect_diffuse", "incident radiance gathered by the diffuse cones",
     "docs/pipeline.md § Diffuse cones and their weights",
     "ref/stages/cone_trace.cpp, ref/stages/indirect_pass.cpp", "gl/gl_pass_shading.cpp (indirect_pass), gl/shaders/cone.glsl"),
    ("image.indirect_specular", "incident radiance of the specular cone", "docs/pipeline.md § Specular cone",
     "ref/stages/cone_trace.cpp, ref/stages/indirect_pass.cpp", "gl/gl_pass_shading.cpp (indirect_pass), gl/shaders/cone.glsl"),
    ("image.soft_shadow", "cone-traced visibility toward the light", "docs/pipeline.md § Soft shadows",
     "ref/stages/soft_shadow.cpp", "gl/gl_pass_shading.cpp (direct_pass), gl/shaders/direct.frag"),
    ("image.particles", "the additive fire particle layer", "docs/pipeline.md § Particles",
     "ref/stages/particles.cpp", "gl/gl_pass_shading.cpp (particle_pass), gl/shaders/particles.frag"),
    ("image.", "a term of the final composite (direct + kd albedo indirect diffuse + F indirect specular + emission)",
     "docs/pipeline.md § Final composite", "ref/stages/composite.cpp",
     "gl/gl_pass_shading.cpp (indirect_pass), gl/shaders/indirect.frag"),
]


def stage_doc(stage):
    """(what, docs, ref source, gl source) for a stage name; None for an unknown name."""
    for prefix, what, docs, ref_src, gl_src in STAGE_DOCS:
        if stage == prefix or stage.startswith(prefix):
            return what, docs, ref_src, gl_src
    return None
