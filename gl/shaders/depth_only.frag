// Depth-only passes (shadow maps, depth pre-pass): the rasterizer writes depth; no colour.
void main() {}
