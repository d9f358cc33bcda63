#include "gl_faults.h"

#include "core/error.h"

namespace vct::gl {

const GlFault* find_gl_fault(const std::string& name) {
  for (const GlFault& f : kGlFaults)
    if (name == f.name) return &f;
  return nullptr;
}

std::string gl_fault_names() {
  std::string out;
  for (const GlFault& f : kGlFaults) out += (out.empty() ? "" : ", ") + std::string(f.name);
  return out;
}

void check_gl_fault(const std::string& name, const std::string& where) {
  if (!name.empty() && !find_gl_fault(name))
    throw InputError(where, "unknown GL fault \"" + name + "\" (known: " + gl_fault_names() + ")");
}

}  // namespace vct::gl
