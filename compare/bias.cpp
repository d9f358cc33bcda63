#include "bias.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "core/math.h"
#include "core/parallel_tasks.h"
#include "io/image_io.h"
#include "stages/stage_registry.h"

namespace vct::cmp {

namespace fs = std::filesystem;

const std::vector<std::pair<std::string, std::string>>& bias_pairs() {
  static const std::vector<std::pair<std::string, std::string>> kPairs = [] {
    std::vector<std::pair<std::string, std::string>> pairs;
    for (const StageRow& row : stage_rows())
      if (*row.pt_aov) pairs.emplace_back(row.name, row.pt_aov);
    return pairs;
  }();
  return kPairs;
}

namespace {

// Diverging map for signed relative error: blue (VCT darker) - white - red (VCT brighter).
vec3 diverging(float t) {
  t = std::clamp(t, -1.0f, 1.0f);
  return t < 0 ? glm::mix(vec3(1.0f), vec3(0.1f, 0.3f, 1.0f), -t) : glm::mix(vec3(1.0f), vec3(1.0f, 0.15f, 0.1f), t);
}

// Luminance standard deviation of the PT mean: channels are strongly correlated (same paths),
// so sigma_lum <= sum_c w_c sigma_c is used: an upper bound, so noise is never called bias.
// The half-split variance of one pixel has one degree of freedom (a Cauchy-tailed z), so it is
// pooled over a 5x5 window (~25 degrees of freedom) before use; the null expectation of the
// beyond-k fraction then comes from Student's t with that many degrees of freedom.
constexpr int kPoolRadius = 2;
constexpr double kPoolDof = double((2 * kPoolRadius + 1) * (2 * kPoolRadius + 1));

Image pool_variance(const Image& var) {
  Image out(var.width, var.height, var.channels);
  for (int y = 0; y < var.height; ++y)
    for (int x = 0; x < var.width; ++x)
      for (int c = 0; c < var.channels; ++c) {
        double s = 0;
        int n = 0;
        for (int dy = -kPoolRadius; dy <= kPoolRadius; ++dy)
          for (int dx = -kPoolRadius; dx <= kPoolRadius; ++dx) {
            const int xx = x + dx, yy = y + dy;
            if (xx < 0 || yy < 0 || xx >= var.width || yy >= var.height) continue;
            s += double(var.at(xx, yy, c));
            ++n;
          }
        out.at(x, y, c) = float(s / n);
      }
  return out;
}

// Two-sided tail P(|T| > k) of Student's t with `dof` degrees of freedom (Simpson's rule).
double student_t_tail(double k, double dof) {
  const double norm = std::exp(std::lgamma((dof + 1) / 2) - std::lgamma(dof / 2)) / std::sqrt(dof * double(kPi));
  auto pdf = [&](double t) { return norm * std::pow(1 + t * t / dof, -(dof + 1) / 2); };
  const double hi = k + 200.0;
  const int n = 20000;
  const double h = (hi - k) / n;
  double s = pdf(k) + pdf(hi);
  for (int i = 1; i < n; ++i) s += (i % 2 ? 4 : 2) * pdf(k + i * h);
  return 2.0 * s * h / 3.0;
}

float sigma_lum(const Image& var, int x, int y) {
  if (var.channels < 3) return std::sqrt(std::max(0.0f, var.at(x, y, 0)));
  const float w[3] = {0.2126f, 0.7152f, 0.0722f};
  float s = 0;
  for (int c = 0; c < 3; ++c) s += w[c] * std::sqrt(std::max(0.0f, var.at(x, y, c)));
  return s;
}

void write_maps(BiasComponent& b, const Image& v, const Image& p, const Image* var, const BiasOptions& opt) {
  if (opt.out_dir.empty()) return;
  fs::create_directories(opt.out_dir);
  const std::string stem = b.component;
  Image heat(v.width, v.height, 3);
  const float eps = float(std::sqrt(kRelMseEpsilon));
  for (int y = 0; y < v.height; ++y)
    for (int x = 0; x < v.width; ++x) {
      const float lv = luminance(v, x, y), lp = luminance(p, x, y);
      heat.set_rgb(x, y, diverging((lv - lp) / (lp + eps)));
    }
  write_png_linear((fs::path(opt.out_dir) / (stem + "_heat.png")).string(), heat, 0.0f, 1.0f);
  b.heatmap = opt.out_prefix + stem + "_heat.png";
  if (!var) return;
  Image z(v.width, v.height, 3);
  for (int y = 0; y < v.height; ++y)
    for (int x = 0; x < v.width; ++x) {
      const float s = sigma_lum(*var, x, y) + 1e-7f;
      const float zz = (luminance(v, x, y) - luminance(p, x, y)) / s;
      z.set_rgb(x, y, diverging(zz / float(2.0 * opt.k)));
    }
  write_png_linear((fs::path(opt.out_dir) / (stem + "_z.png")).string(), z, 0.0f, 1.0f);
  b.zmap = opt.out_prefix + stem + "_z.png";
}

}  // namespace

namespace {
BiasComponent measure_component(const std::string& stage, const std::string& aov, const StageSet& vct,
                                const std::map<std::string, Image>& pt, const BiasOptions& opt) {
  BiasComponent b;
  b.component = aov.substr(3);  // "direct", "indirect_diffuse", ...
  b.vct_stage = stage;
  b.pt_aov = aov;
  b.k = opt.k;
  auto vi = vct.images.find(stage);
  auto pi = pt.find(aov);
  if (vi == vct.images.end() || pi == pt.end()) {
    b.note = vi == vct.images.end() ? "VCT image " + stage + " missing" : "path tracer AOV " + aov + " missing";
    return b;
  }
  const Image& v = vi->second;
  const Image& p = pi->second;
  if (v.width != p.width || v.height != p.height) {
    b.note = "sizes differ (VCT " + std::to_string(v.width) + "x" + std::to_string(v.height) + ", PT " +
             std::to_string(p.width) + "x" + std::to_string(p.height) + ")";
    return b;
  }
  b.available = true;
  b.metrics = image_metrics(v, p);
  auto var_it = pt.find(aov + "_var");
  Image pooled;
  const Image* var = nullptr;
  if (var_it != pt.end() && var_it->second.width == v.width && var_it->second.height == v.height)
    var = &(pooled = pool_variance(var_it->second));
  b.have_variance = var != nullptr;
  b.expected_fraction = student_t_tail(b.k, kPoolDof - 1);
  if (var) {
    double mean_p = 0;
    for (int y = 0; y < v.height; ++y)
      for (int x = 0; x < v.width; ++x) mean_p += double(luminance(p, x, y));
    const double n = double(v.width) * double(v.height);
    mean_p /= n;
    // Floor for pixels whose samples all agreed (sigma = 0): float noise is not bias.
    const double floor = 1e-4 * mean_p + 1e-7;
    size_t beyond = 0;
    double sum_d = 0, sum_var = 0;
    for (int y = 0; y < v.height; ++y)
      for (int x = 0; x < v.width; ++x) {
        const double d = luminance(v, x, y) - luminance(p, x, y);
        const double s = std::max(double(sigma_lum(*var, x, y)), floor);
        beyond += std::abs(d) > b.k * s;
        sum_d += d;
        sum_var += s * s;
      }
    b.fraction_beyond_k_sigma = double(beyond) / n;
    b.mean_bias_z = sum_d / std::sqrt(std::max(sum_var, 1e-30));
    const double pexp = b.expected_fraction;
    b.significant = b.fraction_beyond_k_sigma > 2.0 * pexp + 3.0 * std::sqrt(pexp / n) || std::abs(b.mean_bias_z) > 5.0;
    char buf[200];
    std::snprintf(buf, sizeof buf, "%.2f%% of pixels beyond %.0f sigma (noise alone: %.2f%%); mean bias %.1f sigma: %s",
                  100 * b.fraction_beyond_k_sigma, b.k, 100 * pexp, b.mean_bias_z,
                  b.significant ? "bias beyond PT noise" : "consistent with PT noise");
    b.note = buf;
  } else {
    b.note = "no variance AOV: bias reported without a noise judgement";
  }
  write_maps(b, v, p, var, opt);
  return b;
}
}  // namespace

std::vector<BiasComponent> measure_bias(const StageSet& vct, const std::map<std::string, Image>& pt, const BiasOptions& opt) {
  // One task per component: each writes its own maps and its own slot, so the result and the
  // files are the same for any thread count (docs/performance.md, "Where validate's time goes").
  const auto& pairs = bias_pairs();
  std::vector<BiasComponent> out(pairs.size());
  if (!opt.out_dir.empty()) fs::create_directories(opt.out_dir);
  parallel_tasks(int64_t(pairs.size()), [&](int64_t i) {
    out[size_t(i)] = measure_component(pairs[size_t(i)].first, pairs[size_t(i)].second, vct, pt, opt);
  });
  return out;
}

nlohmann::json to_json(const BiasComponent& b) {
  nlohmann::json j = {{"component", b.component}, {"vct", b.vct_stage},  {"pt", b.pt_aov},
                      {"available", b.available}, {"note", b.note}};
  if (!b.available) return j;
  j["rel_mse"] = b.metrics.rel_mse;
  j["rel_mse_epsilon"] = b.metrics.rel_mse_epsilon;
  j["reference"] = "path tracer";
  j["mse"] = b.metrics.mse;
  j["mean_bias"] = b.metrics.mean_bias;
  j["relative_bias"] = b.metrics.relative_bias;
  j["max_abs"] = b.metrics.max_abs;
  j["ssim"] = b.metrics.ssim;
  j["mean_vct"] = b.metrics.mean_test;
  j["mean_pt"] = b.metrics.mean_reference;
  j["have_variance"] = b.have_variance;
  j["k"] = b.k;
  j["fraction_beyond_k_sigma"] = b.fraction_beyond_k_sigma;
  j["expected_fraction"] = b.expected_fraction;
  j["mean_bias_z"] = b.mean_bias_z;
  j["significant"] = b.significant;
  j["heatmap"] = b.heatmap;
  j["zmap"] = b.zmap;
  return j;
}

std::map<std::string, Image> read_pt_aovs(const std::string& dir) {
  std::map<std::string, Image> out;
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) return out;
  for (const auto& e : fs::directory_iterator(dir, ec)) {
    const fs::path p = e.path();
    const std::string stem = p.stem().string();
    if (p.extension() == ".exr" && stem.rfind("pt_", 0) == 0) out[stem] = read_image(p.string());
  }
  return out;
}

}  // namespace vct::cmp
