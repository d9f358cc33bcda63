#include "compare/rule_masks.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "io/image_io.h"

namespace vct::cmp {

namespace {

vec3 rule_colour(Rule r) {
  const auto& c = admission_row(r).colour;
  return vec3(float(c[0]), float(c[1]), float(c[2])) / 255.0f;
}

bool paints(Rule r) { return !within_bound_rule(r) && r != Rule::OwnInputs && r != Rule::MarchEnd; }

void write_mask_png(const CompareOptions& opt, StageVerdict& v, const Image& m) {
  std::filesystem::create_directories(opt.mask_dir);
  write_png_linear((std::filesystem::path(opt.mask_dir) / (mask_stem(v.stage) + ".png")).string(), m, 0.0f, 1.0f);
  v.mask = opt.mask_prefix + mask_stem(v.stage) + ".png";
}

}  // namespace

std::string mask_stem(const std::string& stage) {
  std::string s = stage;
  std::replace(s.begin(), s.end(), '.', '_');
  return s + "_mask";
}

void write_image_rule_mask(const CompareOptions& opt, StageVerdict& v, const Image& ref, const std::vector<Rule>& rules) {
  if (opt.mask_dir.empty()) return;
  Image m(ref.width, ref.height, 3);
  float peak = 1e-6f;
  for (int y = 0; y < ref.height; ++y)
    for (int x = 0; x < ref.width; ++x) peak = std::max(peak, std::abs(ref.at(x, y, 0)));
  for (int y = 0; y < ref.height; ++y)
    for (int x = 0; x < ref.width; ++x) {
      const Rule r = rules[size_t(y) * size_t(ref.width) + size_t(x)];
      const float g = 0.35f * std::min(1.0f, std::abs(ref.at(x, y, 0)) / peak);
      m.set_rgb(x, y, paints(r) ? rule_colour(r) : vec3(g));
    }
  write_mask_png(opt, v, m);
}

void write_volume_rule_mask(const CompareOptions& opt, StageVerdict& v, const Volume& context,
                            const std::vector<Rule>& rules) {
  if (opt.mask_dir.empty() || v.out_of_bound == 0) return;
  const int nx = context.nx, ny = context.ny, nz = context.nz;
  // As write_volume_montage lays slices out: every step-th z slice, a 1-voxel gap, +y up.
  const int step = std::max(1, (nz + 63) / 64), slices = (nz + step - 1) / step;
  const int cols = int(std::ceil(std::sqrt(double(slices)))), rows_n = (slices + cols - 1) / cols;
  Image m((nx + 1) * cols, (ny + 1) * rows_n, 3, 0.0f);
  for (int s = 0; s < slices; ++s) {
    const int z = s * step, ox = (s % cols) * (nx + 1), oy = (s / cols) * (ny + 1);
    for (int y = 0; y < ny; ++y)
      for (int x = 0; x < nx; ++x) {
        const Rule r = rules[(size_t(z) * size_t(ny) + size_t(y)) * size_t(nx) + size_t(x)];
        const float occupied = context.voxel(x, y, z)[context.channels >= 4 ? 3 : 0] > 0.0f ? 0.2f : 0.0f;
        m.set_rgb(ox + x, oy + (ny - 1 - y), paints(r) ? rule_colour(r) : vec3(occupied));
      }
  }
  write_mask_png(opt, v, m);
}

nlohmann::json mask_legend() {
  nlohmann::json legend = nlohmann::json::array();
  for (const AdmissionRow& row : admission_table())
    if (paints(row.rule)) legend.push_back({{"rule", row.name}, {"colour", row.colour}});
  return legend;
}

}  // namespace vct::cmp
