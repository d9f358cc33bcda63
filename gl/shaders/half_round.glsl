// Pinning GL's store conversions (docs/gl_backend.md, "Formats").
// Round-to-nearest-even to binary16, computed exactly in float: the result is representable in
// half precision, so the driver's own float->half conversion on imageStore (whose rounding GL
// leaves to the implementation; llvmpipe truncates) has nothing left to round. This pins RGBA16F
// voxels to ref/stages/reduction.cpp's quantize_half bit for bit.
float round_to_half(float v) {
  if (isnan(v) || isinf(v)) return v;
  float a = abs(v);
  float r;
  if (a >= 65520.0f) {
    r = uintBitsToFloat(0x7f800000u);  // rounds to infinity, as IEEE overflow does
  } else if (a < 6.103515625e-05f) {
    r = roundEven(a * 16777216.0f) / 16777216.0f;  // subnormal halves: steps of 2^-24 (exact scaling)
  } else {
    int e;
    frexp(a, e);  // a = m * 2^e, m in [0.5, 1): 11 significant bits keep steps of 2^(e-11)
#ifdef VCT_FAULT_HALF_TRUNCATE
    r = ldexp(trunc(ldexp(a, 11 - e)), e - 11);  // fault: truncates instead of rounding to nearest even
#else
    r = ldexp(roundEven(ldexp(a, 11 - e)), e - 11);
#endif
  }
  return v < 0.0f ? -r : r;
}
vec4 round_to_half(vec4 v) {
  return vec4(round_to_half(v.x), round_to_half(v.y), round_to_half(v.z), round_to_half(v.w));
}

// RGBA8 stores: GL's float->unorm8 conversion may round or truncate (llvmpipe rounds to nearest:
// tests/gl/gl_store_conversion_test.cpp). The
// value is rounded here (to nearest even, as the CPU's quantize_unorm8) and a quarter step is
// added, so either conversion lands on the same integer.
vec4 unorm8_store_value(vec4 v) {
  vec4 q = roundEven(clamp(v, vec4(0.0f), vec4(1.0f)) * 255.0f);
  return (q + 0.25f) / 255.0f;
}

// The value to imageStore for the voxel storage format: u_storage_format 0 = RGBA16F, 1 = RGBA8.
vec4 storage_value(vec4 v, int format) { return format == 1 ? unorm8_store_value(v) : round_to_half(v); }
