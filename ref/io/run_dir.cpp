#include "io/run_dir.h"

#include <sys/utsname.h>
#include <unistd.h>

#include <OpenImageIO/oiioversion.h>
#include <embree3/rtcore_config.h>
#include <filesystem>
#include <fstream>
#include <glm/detail/setup.hpp>

#include "core/error.h"
#include "core/parallel.h"
#include "io/atomic_file.h"
#include "io/image_io.h"
#include "io/nrrd.h"

namespace vct {

namespace fs = std::filesystem;

RunDir::RunDir(std::string path) : path_(std::move(path)) {
  std::error_code ec;
  if (fs::exists(path_, ec) && !fs::is_directory(path_, ec))
    throw InputError(path_, "exists and is not a directory; cannot use it as a run directory");
  fs::create_directories(path_, ec);
  if (ec) throw InputError(path_, "cannot create run directory: " + ec.message());
  json_["format"] = "vct-run/1";
}

std::string RunDir::file(const std::string& relative) const { return (fs::path(path_) / relative).string(); }

void RunDir::write_color(const std::string& name, const Image& img, float exposure) {
  write_exr(file(name + ".exr"), img);
  write_png(file(name + ".png"), img, exposure);
}

void RunDir::write_data(const std::string& name, const Image& img, float lo, float hi) {
  write_exr(file(name + ".exr"), img);
  write_png_linear(file(name + ".png"), img, lo, hi);
}

void RunDir::write_volume(const std::string& name, const Volume& vol, float spacing, float exposure) {
  write_nrrd(file(name + ".nrrd"), vol, spacing);
  write_volume_montage(file(name + ".png"), vol, 64, exposure);
}

void RunDir::add_timing(const std::string& backend, const std::string& stage, double ms) {
  json_["timings_ms"][backend][stage] = ms;
}

void RunDir::save() const { write_text_atomically(file("run.json"), json_.dump(2) + "\n"); }

namespace {
std::string cpu_model() {
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("model name", 0) == 0) return line.substr(line.find(':') + 2);
  return "unknown";
}
}  // namespace

nlohmann::json environment_info() {
  utsname u{};
  uname(&u);
  return {{"vct_version", "0.1.0"},
          {"os", std::string(u.sysname) + " " + u.release},
          {"cpu", cpu_model()},
          {"cores", int(sysconf(_SC_NPROCESSORS_ONLN))},
          {"threads", thread_count()},
          {"compiler", std::string("gcc ") + __VERSION__},
          {"openimageio", OIIO_VERSION_STRING},
          {"embree", RTC_VERSION_STRING},
          {"glm", GLM_VERSION}};
}

}  // namespace vct
