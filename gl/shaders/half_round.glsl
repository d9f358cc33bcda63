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
    r = ldexp(roundEven(ldexp(a, 11 - e)), e - 11);
  }
  return v < 0.0f ? -r : r;
}
vec4 round_to_half(vec4 v) {
  return vec4(round_to_half(v.x), round_to_half(v.y), round_to_half(v.z), round_to_half(v.w));
}
