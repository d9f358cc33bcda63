// Volumes on disk as NRRD 0004 (gzip-encoded little-endian float, channels as the fastest axis), readable
// by ParaView, 3D Slicer, Fiji and pynrrd; plus a PNG montage of z slices for looking.
#pragma once

#include <string>

#include "core/volume.h"

namespace vct {

/// Writes `vol` as an attached-header NRRD, gzip-encoded. `spacing` is the world size of one voxel.
void write_nrrd(const std::string& path, const Volume& vol, float spacing = 1.0f);

/// Reads a NRRD written by us or by another tool (float, uint8, uint16, int32; raw or gzip
/// encoding); throws InputError naming the problem.
Volume read_nrrd(const std::string& path);

/// A grid of z slices (RGB from the first three channels, or grey for one channel), tone-mapped
/// for RGB volumes and linear [0,1] for one-channel ones. At most `max_slices` slices shown.
void write_volume_montage(const std::string& path, const Volume& vol, int max_slices = 64, float exposure = 1.0f);

}  // namespace vct
