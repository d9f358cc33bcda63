// The largest image vct reads: a frame of the largest size it renders (validate_settings: 16384
// per side) with RGBA channels. File headers are checked against these before anything is
// allocated from them, since a header may claim far more than its compressed bytes hold.
#pragma once

namespace vct {

inline constexpr long long kMaxImageSide = 16384;
inline constexpr long long kMaxImageValues = kMaxImageSide * kMaxImageSide * 4;  // width x height x channels
// The widest image vct writes is the reference's gbuffer.tie_range (42 channels: every G-buffer
// stage's lo and hi, freedoms/gbuffer_ties.h); the values cap above still bounds the allocation.
inline constexpr long long kMaxImageChannels = 64;
inline constexpr long long kMaxExrTileSide = 4096;  // OpenEXR allocates a tile buffer per tile size

}  // namespace vct
