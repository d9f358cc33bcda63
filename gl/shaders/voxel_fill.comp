// Solid voxelization and surface thickening (docs/pipeline.md, "Solid voxelization and surface
// thickening"), after the resolve and before the mips: each empty voxel GATHERS from the surface
// occupancy (the voxelization's fragment counts) and the facing masks its fragments wrote; the
// CPU's ref/stages/voxel_fill.cpp scatters from the surface instead. A filled voxel keeps its RGB
// (0, or the particles' light) and gets opacity 1.
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;
layout(binding = 0, r32ui) uniform readonly uimage3D u_count;
layout(binding = 1, r32ui) uniform readonly uimage3D u_facing;
layout(binding = 2, VCT_VOXEL_FORMAT) uniform image3D u_voxels;  // each invocation its own voxel
uniform int u_grid;
uniform int u_solid_voxelization;
uniform int u_surface_thickening_voxels;

// Unit steps of the six facing directions, in sh's AnisoDir order (+x, -x, +y, -y, +z, -z).
const ivec3 STEPS[6] = ivec3[6](ivec3(1, 0, 0), ivec3(-1, 0, 0), ivec3(0, 1, 0), ivec3(0, -1, 0),
                                ivec3(0, 0, 1), ivec3(0, 0, -1));

bool in_grid(ivec3 c) { return all(greaterThanEqual(c, ivec3(0))) && all(lessThan(c, ivec3(u_grid))); }
bool surface(ivec3 c) { return imageLoad(u_count, c).r > 0u; }

// Walks from c along direction d: is the first surface voxel met one that does not face back
// toward c (no triangle of facing d ^ 1 there)? False when the ray leaves the grid first.
bool closed_along(ivec3 c, int d) {
  for (ivec3 p = c + STEPS[d]; in_grid(p); p += STEPS[d])
    if (surface(p)) return (imageLoad(u_facing, p).r & (1u << uint(d ^ 1))) == 0u;
  return false;
}

bool enclosed(ivec3 c) {
  for (int d = 0; d < 6; ++d)
    if (!closed_along(c, d)) return false;
  return true;
}

// Is c among the k voxels behind a surface voxel s facing d, i.e. s = c + j * STEPS[d], j in 1..k?
bool behind_surface(ivec3 c) {
  for (int d = 0; d < 6; ++d)
    for (int j = 1; j <= u_surface_thickening_voxels; ++j) {
      ivec3 s = c + j * STEPS[d];
      if (!in_grid(s)) break;
      if (surface(s) && (imageLoad(u_facing, s).r & (1u << uint(d))) != 0u) return true;
    }
  return false;
}

void main() {
  ivec3 c = ivec3(gl_GlobalInvocationID);
  if (!in_grid(c) || surface(c)) return;
  bool fill = (u_solid_voxelization != 0 && enclosed(c)) ||
              (u_surface_thickening_voxels > 0 && behind_surface(c));
  if (!fill) return;
  vec4 v = imageLoad(u_voxels, c);
  imageStore(u_voxels, c, vec4(v.rgb, 1.0f));
}
