#include "gl_device_list.h"

#include <exception>
#include <string>

#include "gl_context.h"
#include "gl_device.h"
#include "gl_facts.h"

namespace vct::gl {
namespace {

nlohmann::json probe(const std::string& spec) {
  nlohmann::json j;
  try {
    GlContext context(spec);
    j["status"] = "ok";
    j["facts"] = read_driver_facts(context, context.max_framebuffer_samples());
  } catch (const std::exception& e) {
    j["status"] = std::string("unavailable: ") + e.what();
  }
  return j;
}

}  // namespace

nlohmann::json list_gl_devices() {
  nlohmann::json devices = nlohmann::json::array();
  for (const EglDevice& d : list_egl_devices()) {
    nlohmann::json j = probe(std::to_string(d.index));
    j["spec"] = std::to_string(d.index);
    j["kind"] = d.software ? "software" : "hardware";
    j["egl"] = {{"extensions", d.extensions}, {"drm_file", d.drm_file}, {"render_node", d.render_node}};
    devices.push_back(j);
  }
  nlohmann::json s = probe(kSurfacelessDevice);
  s["spec"] = kSurfacelessDevice;
  s["kind"] = "surfaceless";
  devices.push_back(s);
  std::string chosen;
  try {
    GlContext automatic;
    chosen = automatic.device();
  } catch (const std::exception&) {
  }
  return {{"devices", devices}, {"default", chosen}};
}

}  // namespace vct::gl
