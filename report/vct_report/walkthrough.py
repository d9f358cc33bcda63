"""The walkthrough: one section per pipeline step, in order, with what the step does and the
settings that drive it (keys as in run.json["settings"]["vct"]). Which stages each step shows is
the stage registry's walkthrough_step column (report/vct_report/registry.py), not a list here."""

STAGES = [
    ("shadow", "Shadow map", "Each light renders the scene's depth from its own point of view into D32F depth maps: "
     "a spot one perspective square map, a directional light one orthographic map fitted to the voxel volume, "
     "a point light a cube of six 90-degree faces (shadow_map_cube.<light x 6 + face>). Later, a surface point is lit if its depth seen from the light is not "
     "behind the stored depth plus a constant bias, looked up a little off the surface along its normal (the normal offset, "
     "which keeps a surface from shadowing itself); PCF averages a k x k block of such tests for soft edges.",
     ["shadow_map_size", "pcf_kernel", "shadow_bias"], "shadow_maps"),
    ("gbuffer", "G-buffer", "The camera pass rasterizes the scene once and stores, per pixel centre, everything shading needs: "
     "world position, shading normal (after normal mapping), base colour, metallic/roughness/specular, "
     "emission, depth and coverage. All later screen-space stages read only these images.",
     ["width", "height"], "gbuffer"),
    ("direct", "Direct light", "Cook-Torrance (GGX, Schlick, Smith) from every light, with the shadow-map visibility (or the "
     "cone-traced visibility when soft shadows are on). The light model decides the falloff: glTF "
     "(candela, inverse square; a directional light's lux has no falloff) or the seed's smoothstep x 1/(1+d).",
     ["light_model", "pcf_kernel", "shadow_bias", "shadow_normal_offset", "soft_shadows"], "direct"),
    ("voxelize", "Voxelization", "Every triangle is projected along its dominant axis and rasterized into an N^3 grid; each covered "
     "sample becomes a fragment in one voxel. The CPU reference also computes the exact conservative set "
     "(triangle-box overlap) so that holes of the sample rule can be told apart from GPU bugs.",
     ["grid", "voxelizer", "msaa_samples"], "voxelize"),
    ("inject", "Injected light", "Each voxel stores the light leaving its surfaces (albedo x irradiance / pi + emission, plus the "
     "previous frame's bounce with multibounce) and opacity 1. Fragments in one voxel are averaged: "
     "exactly (CPU), with fixed-point integer sums, or with the CAS RGBA8 running average.",
     ["storage", "reduction", "bounces", "restitution"], "inject_mips_multibounce"),
    ("mips", "Mip levels", "Level l+1 averages 2x2x2 voxels of level l (isotropic), or, anisotropically, composites pairs "
     "front-to-back along each of six directions and averages the four pairs. Cones sample coarser "
     "levels as they widen.",
     ["anisotropic"], None),
    ("explain", "Cones of one pixel", "One pixel's cones drawn over the grid: the diffuse cone set around the normal (one along it and "
     "diffuse_cone_count - 1 tilted by diffuse_cone_tilt_deg, evenly spaced in azimuth; the seed's set is "
     "5 at 45 degrees; cosine-weighted) and one specular cone along the reflected view direction. Each "
     "step samples the mip level whose voxel matches the cone's diameter and accumulates front to back "
     "until opaque.",
     ["diffuse_cone_count", "diffuse_cone_tilt_deg", "diffuse_aperture_deg", "cone_quality", "cone_offset_voxels",
      "max_distance", "diffuse_weighting"], None),
    ("indirect_diffuse", "Indirect diffuse", "Incident radiance gathered by the diffuse cones; the final image adds kd x albedo x this term.",
     ["diffuse_cones", "diffuse_cone_count", "diffuse_cone_tilt_deg", "diffuse_aperture_deg", "random_rotation"],
     "indirect_cones"),
    ("specular", "Indirect specular", "One cone along the reflected view vector, its aperture from the roughness; the final image adds F x this term.",
     ["specular_cones"], None),
    ("soft", "Soft shadows", "Optional: a narrow cone toward the light accumulates opacity, replacing the shadow-map test.",
     ["soft_shadows", "soft_shadow_aperture_deg"], None),
    ("multibounce", "Multibounce frames", "Temporal multibounce: frame n injects direct light plus restitution x albedo x the diffuse cones "
     "traced in frame n-1's mips; the total voxel energy per frame should converge.",
     ["bounces", "restitution", "convergence_tolerance"], None),
    ("final", "Final composite", "final = direct + kd albedo indirect diffuse + F indirect specular + emission (+ additive particles), "
     "linear HDR; the PNGs show it through the Khronos PBR Neutral tone mapper and the sRGB curve.",
     ["particles", "time"], "composite"),
]
