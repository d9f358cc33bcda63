#include "pt/partial_sums.h"

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "core/error.h"
#include "io/atomic_file.h"

namespace vct::pt {

namespace {

template <class T>
void put(std::ofstream& out, const T& v) {
  out.write(reinterpret_cast<const char*>(&v), sizeof(T));
}
template <class T>
void get(std::ifstream& in, T& v) {
  in.read(reinterpret_cast<char*>(&v), sizeof(T));
}

std::string range_text(const PartialSums& p) {
  return "samples " + std::to_string(p.first_sample) + ".." + std::to_string(p.end_sample);
}

}  // namespace

void save_partial_sums(const std::string& path, const PartialSums& p) {
  write_atomically(path, [&](const std::string& tmp) {
    std::ofstream out(tmp, std::ios::binary);
    out.write(kPartialSumsMagic, 8);
    put(out, p.key.scene_hash);
    put(out, p.key.settings_hash);
    put(out, int32_t(p.sums.width()));
    put(out, int32_t(p.sums.height()));
    put(out, p.first_sample);
    put(out, p.end_sample);
    put(out, uint32_t(Accumulator::kValuesPerPixel));
    for (uint64_t v : {p.rays.primary, p.rays.secondary, p.rays.shadow, p.rays.nonfinite_samples}) put(out, v);
    out.write(reinterpret_cast<const char*>(p.sums.sums().data()),
              std::streamsize(p.sums.sums().size() * sizeof(double)));
    out.close();
    if (!out) throw InputError(tmp, "cannot write partial sums");
  });
}

PartialSums load_partial_sums(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "cannot open partial sums");
  char magic[8] = {};
  PartialSums p;
  int32_t w = 0, h = 0;
  uint32_t values = 0;
  in.read(magic, 8);
  get(in, p.key.scene_hash);
  get(in, p.key.settings_hash);
  get(in, w);
  get(in, h);
  get(in, p.first_sample);
  get(in, p.end_sample);
  get(in, values);
  for (uint64_t* v : {&p.rays.primary, &p.rays.secondary, &p.rays.shadow, &p.rays.nonfinite_samples}) get(in, *v);
  if (!in || std::memcmp(magic, kPartialSumsMagic, 8) != 0 || values != uint32_t(Accumulator::kValuesPerPixel))
    throw InputError(path, "not a partial-sums file of this format");
  if (w <= 0 || h <= 0 || w > 65536 || h > 65536 || p.first_sample >= p.end_sample)
    throw InputError(path, "partial sums with an empty range or image");
  p.sums = Accumulator(w, h);
  in.read(reinterpret_cast<char*>(p.sums.sums().data()), std::streamsize(p.sums.sums().size() * sizeof(double)));
  if (!in || in.peek() != std::char_traits<char>::eof())
    throw InputError(path, "partial sums are truncated or have trailing bytes");
  p.sums.set_samples(p.end_sample);
  return p;
}

Accumulator merge_partial_sums(std::vector<PartialSums> partials, const CheckpointKey& key, int width, int height,
                               uint32_t spp, RayCounts& rays) {
  if (partials.empty()) throw InputError("merge", "no partial sums to merge");
  std::sort(partials.begin(), partials.end(),
            [](const PartialSums& a, const PartialSums& b) { return a.first_sample < b.first_sample; });
  Accumulator total;
  uint32_t next = 0;
  rays = RayCounts{};
  for (const PartialSums& p : partials) {
    const std::string what = range_text(p);
    if (p.key.scene_hash != key.scene_hash) throw InputError(what, "partial sums of a different scene");
    if (p.key.settings_hash != key.settings_hash || p.sums.width() != width || p.sums.height() != height)
      throw InputError(what, "partial sums made with different path tracer settings");
    if (p.first_sample != next)
      throw InputError(what, "expected a range starting at sample " + std::to_string(next) + " (gap or overlap)");
    if (next == 0) {
      total = p.sums;
    } else {
      std::vector<double>& t = total.sums();
      const std::vector<double>& s = p.sums.sums();
      for (size_t i = 0; i < t.size(); ++i) t[i] += s[i];  // element by element, in range order
    }
    rays.add(p.rays);
    next = p.end_sample;
  }
  if (next != spp)
    throw InputError("merge", "partial sums cover samples 0.." + std::to_string(next) + ", not the requested " +
                                  std::to_string(spp));
  total.set_samples(spp);
  return total;
}

}  // namespace vct::pt
