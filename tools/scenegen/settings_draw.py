"""Random settings for generated scenes: one row per settings-table key that `vct validate` accepts
on every backend it runs (ref, gl on llvmpipe, pt), with the values drawn. Keys must exist in
the settings table (`vct settings`; tests/scenegen/test_scenegen.py checks it). Left out on
purpose: conservative_raster nv|intel (exit 3 without the extension); the reference-only settings
GL refuses with exit 2 (shadow_compare linear, shadow_depth_format, cone_tangent_frame,
specular_aperture, specular_view, indirect_fresnel, explicit shadow matrices and cone sets);
pt.* and threads (the judge's side, not the scene's); time, frame and particles (generated scenes
have no particles); width, height, grid and shadow_map_size (generate.py draws them per size
class: they set a run's cost, and validate's default 1024^2 map costs the reference 8x the
render time of a 256^2 one on a small scene)."""

CHOICES = {
    "pcf_kernel": [1, 2, 3, 4, 5],
    "light_model": ["gltf", "seed"],
    "msaa_samples": [1, 4, 8],
    "storage": ["rgba8", "rgba16f"],
    "reduction": ["fixed", "cas"],
    "anisotropic": [True, False],
    "solid_voxelization": [True, False],
    "surface_thickening_voxels": [0, 1, 2],
    "diffuse_cones": [True, False],
    "specular_cones": [True, False],
    "soft_shadows": [True, False],
    "diffuse_aperture_deg": [10.0, 30.0, 60.0, 90.0],
    "diffuse_cone_count": [1, 3, 5, 9, 16],
    "diffuse_cone_tilt_deg": [20.0, 45.0, 70.0],
    "diffuse_weighting": ["cosine", "seed"],
    "random_rotation": [True, False],
    "cone_quality": [0.25, 0.5, 1.0, 1.5],
    "cone_offset_voxels": [0.5, 1.0, 1.5, 3.0],
    "cone_start": ["axis", "normal"],
    "bounces": [1, 2, 3],
    "restitution": [0.25, 0.5, 1.0],
    "opacity_step_correction": [True, False],
    "depth_prepass": [True, False],
    "max_distance": [0.5, 1.0, 1.7320508],
}


def draw(rng, max_keys=6):
    """A few keys (0..max_keys) with a value each; keys in table order (deterministic output)."""
    keys = list(CHOICES)
    count = int(rng.integers(0, max_keys + 1))
    picked = sorted(rng.choice(len(keys), size=count, replace=False)) if count else []
    out = {}
    for k in picked:
        values = CHOICES[keys[k]]
        v = values[int(rng.integers(len(values)))]
        out[keys[k]] = v.item() if hasattr(v, "item") else v
    return out
