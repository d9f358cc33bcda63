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

/// The complete source of an embedded shader file (prelude + `defines` + shared header +
/// includes). `defines` is whole lines, e.g. "#define VCT_FAULT_WRONG_MIP 1\n".
std::string assemble_shader(const std::string& file, const std::string& defines = "");

/// The same for a program's own shader text `text` (its `#include "x"` lines name embedded files):
/// a program that embeds the frame writes its own passes with our includes (tests/capture).
std::string assemble_source(const std::string& name, const std::string& text, const std::string& defines = "");

/// Source for `file`, with its stage guessed from the extension (.vert/.geom/.frag/.comp).
ShaderSource shader_file(const std::string& file, const std::string& defines = "");

class Program {
 public:
  Program() = default;
  explicit Program(const std::vector<ShaderSource>& stages);
  /// Convenience: embedded files by name, e.g. {"fullscreen.vert", "direct.frag"}.
  static Program from_files(const std::vector<std::string>& files, const std::string& defines = "");

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

/// Builds every program of one frame with the same prelude defines: the frame's deliberate fault
/// (gl_faults.h) reaches its shaders here, and only here.
class ProgramBuilder {
 public:
  ProgramBuilder() = default;
  /// `fault`: "" or a name of kGlFaults; a shader fault becomes `#define VCT_FAULT_<NAME> 1`.
  explicit ProgramBuilder(const std::string& fault);
  Program build(const std::vector<std::string>& files) const { return Program::from_files(files, defines_); }
  const std::string& defines() const { return defines_; }

 private:
  std::string defines_;
};

}  // namespace vct::gl
