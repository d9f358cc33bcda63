#include "attribution_outputs.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "attribution/budget_images.h"
#include "io/image_io.h"

namespace vct::app {

namespace {

// Heat-map PNGs are enlarged (nearest neighbour) to at least 256 pixels wide, so a 64^2 budget
// can be read in the report; the EXR keeps the pixels as computed.
Image enlarged(const Image& img) {
  const int k = std::max(1, 256 / std::max(img.width, 1));
  Image out(img.width * k, img.height * k, img.channels);
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x)
      for (int c = 0; c < img.channels; ++c) out.at(x, y, c) = img.at(x / k, y / k, c);
  return out;
}

// Waterfall per component, heat map (EXR of the RGB difference + PNG of its luminance) per term.
nlohmann::json write_budget_images(const RunDir& run, const attr::ComponentBudget& b, const Image& mask) {
  nlohmann::json files;
  const std::string stem = "attribution/" + b.component;
  std::filesystem::create_directories(run.file("attribution"));
  write_png_linear(run.file(stem + "_waterfall.png"), attr::waterfall_image(b), 0.0f, 1.0f);
  files["waterfall"] = stem + "_waterfall.png";
  for (const attr::Term& t : b.terms) {
    const std::string name = stem + "_" + t.name;
    float scale = 0.0f;
    write_exr(run.file(name + ".exr"), t.image.value);
    write_png_linear(run.file(name + ".png"), enlarged(attr::term_heat_image(t.image, mask, &scale)), 0.0f, 1.0f);
    files["heat_maps"][t.name] = {{"exr", name + ".exr"}, {"png", name + ".png"}, {"scale", scale}};
  }
  return files;
}

}  // namespace

void print_budget(const attr::ComponentBudget& b, const std::string& prefix) {
  const double total = b.total.value.mean;
  for (size_t k = 0; k < b.rungs.size(); ++k)
    std::printf("%s%-18s rung %-18s %12.6f  +- %.6f\n", prefix.c_str(), b.component.c_str(), b.rung_names[k].c_str(),
                b.rungs[k].mean, b.rungs[k].se);
  for (const attr::Term& t : b.terms)
    std::printf("%s%-18s term %-18s %+12.6f  +- %.6f  %6.1f%%\n", prefix.c_str(), b.component.c_str(),
                t.name.c_str(), t.value.mean, t.value.se, total != 0.0 ? 100.0 * t.value.mean / total : 0.0);
  std::printf("%s%-18s      %-18s %+12.6f  +- %.6f  (sum of terms %+.6f; sum - total %+.6f +- %.6f: %s)\n",
              prefix.c_str(), b.component.c_str(), "total", total, b.total.value.se, b.sum_of_terms, b.discrepancy,
              b.discrepancy_se, b.sums_to_total() ? "adds up" : "DOES NOT ADD UP");
}

nlohmann::json write_attribution(const RunDir& run, const attr::Attribution& a, const Image& mask) {
  nlohmann::json j = attr::to_json(a);
  for (size_t i = 0; i < a.components.size(); ++i) j[i]["files"] = write_budget_images(run, a.components[i], mask);
  return j;
}

}  // namespace vct::app
