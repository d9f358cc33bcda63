// GLSL programs built from the embedded shader files (gl/shaders/*, ref/shared/vct_shared.h).
// Every shader's source is "#version 450\n#define VCT_GLSL 1\n" + vct_shared.h + the file, with
// `#include "name"` lines in our own files replaced by the named embedded file. Compile and link
// errors throw std::runtime_error whose text names the shader file and carries the driver's log.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "core/math.h"
#include "gl_api.h"

namespace vct::gl {

const std::map<std::string, std::string>& embedded_files();

/// One stage of a program: its GL type, a name used in messages, and its full source.
struct ShaderSource {
  GLenum type;
  std::string name;
  std::string source;
};

/// Debug fault switch (VctSettings::gl_fault): while set to a non-empty name, every assembled
/// shader starts with `#define VCT_FAULT_<NAME> 1` (upper case), which turns on that shader's
/// deliberate bug. render_gl_frame sets it for the frame (ScopedShaderFault) and clears it after.
void set_shader_fault(const std::string& name);
struct ScopedShaderFault {
  explicit ScopedShaderFault(const std::string& name) { set_shader_fault(name); }
  ~ScopedShaderFault() { set_shader_fault(""); }
  ScopedShaderFault(const ScopedShaderFault&) = delete;
  ScopedShaderFault& operator=(const ScopedShaderFault&) = delete;
};

/// The complete source of an embedded shader file (prelude + shared header + includes).
std::string assemble_shader(const std::string& file);

/// Source for `file`, with its stage guessed from the extension (.vert/.geom/.frag/.comp).
ShaderSource shader_file(const std::string& file);

class Program {
 public:
  Program() = default;
  explicit Program(const std::vector<ShaderSource>& stages);
  /// Convenience: embedded files by name, e.g. {"fullscreen.vert", "direct.frag"}.
  static Program from_files(const std::vector<std::string>& files);

  GLuint id() const { return id_; }
  void use() const;
  GLint location(const char* name) const;
  // Uniform setters; unknown names are ignored (the compiler may drop unused uniforms).
  void set(const char* name, int v) const;
  void set(const char* name, unsigned v) const;
  void set(const char* name, float v) const;
  void set(const char* name, const vec2& v) const;
  void set(const char* name, const vec3& v) const;
  void set(const char* name, const vec4& v) const;
  void set(const char* name, const ivec3& v) const;
  void set(const char* name, const mat3& v) const;
  void set(const char* name, const mat4& v) const;

 private:
  GLuint id_ = 0;  // owned by the context (all objects die with it)
};

}  // namespace vct::gl
