// The largest image vct reads: a frame of the largest size it renders (validate_settings: 16384
// per side) with RGBA channels. File headers are checked against these before anything is
// allocated from them, since a header may claim far more than its compressed bytes hold.
#pragma once

namespace vct {

inline constexpr long long kMaxImageSide = 16384;
inline constexpr long long kMaxImageValues = kMaxImageSide * kMaxImageSide * 4;  // width x height x channels
inline constexpr long long kMaxImageChannels = 16;                               // as read_nrrd
inline constexpr long long kMaxExrTileSide = 4096;  // OpenEXR allocates a tile buffer per tile size

}  // namespace vct
