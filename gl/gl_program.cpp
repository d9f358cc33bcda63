#include "gl_program.h"

#include <algorithm>
#include <cctype>
#include <sstream>
#include <stdexcept>

#include "gl_context.h"
#include "gl_faults.h"

namespace vct::gl {
namespace {

const std::string& embedded(const std::string& name) {
  const auto& files = embedded_files();
  const auto it = files.find(name);
  if (it == files.end()) throw std::runtime_error("shader " + name + ": no such embedded file");
  return it->second;
}

// Replaces `#include "x"` lines by the embedded file x (recursively, each file once).
std::string expand_includes(const std::string& name, const std::string& text, std::vector<std::string>& seen,
                            int depth) {
  if (depth > 8) throw std::runtime_error("shader " + name + ": #include nesting too deep");
  std::istringstream in(text);
  std::string line, out;
  while (std::getline(in, line)) {
    const auto first = line.find_first_not_of(" \t");
    if (first != std::string::npos && line.compare(first, 8, "#include") == 0) {
      const auto q0 = line.find('"'), q1 = line.rfind('"');
      if (q0 == std::string::npos || q1 <= q0) throw std::runtime_error("shader " + name + ": bad #include: " + line);
      const std::string inc = line.substr(q0 + 1, q1 - q0 - 1);
      // Not one of ours (e.g. the C++-only include of a shared header, inside #ifndef VCT_GLSL):
      // left for the GLSL preprocessor, which skips it in the disabled group.
      if (embedded_files().count(inc) == 0) {
        out += line + "\n";
        continue;
      }
      bool already = false;
      for (const auto& s : seen) already = already || s == inc;
      if (!already) {
        seen.push_back(inc);
        out += expand_includes(inc, embedded(inc), seen, depth + 1);
      }
      out += "\n";
      continue;
    }
    out += line + "\n";
  }
  return out;
}

GLenum stage_of(const std::string& file) {
  auto ends = [&](const char* ext) {
    const std::string e(ext);
    return file.size() >= e.size() && file.compare(file.size() - e.size(), e.size(), e) == 0;
  };
  if (ends(".vert")) return GL_VERTEX_SHADER;
  if (ends(".geom")) return GL_GEOMETRY_SHADER;
  if (ends(".frag")) return GL_FRAGMENT_SHADER;
  if (ends(".comp")) return GL_COMPUTE_SHADER;
  throw std::runtime_error("shader " + file + ": unknown stage (extension)");
}

std::string shader_log(GLuint shader) {
  GLint len = 0;
  glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &len);
  std::string log(size_t(std::max(len, 1)), '\0');
  glGetShaderInfoLog(shader, len, nullptr, log.data());
  return log.c_str();
}

std::string program_log(GLuint program) {
  GLint len = 0;
  glGetProgramiv(program, GL_INFO_LOG_LENGTH, &len);
  std::string log(size_t(std::max(len, 1)), '\0');
  glGetProgramInfoLog(program, len, nullptr, log.data());
  return log.c_str();
}

}  // namespace

ProgramBuilder::ProgramBuilder(const std::string& fault) {
  check_gl_fault(fault, "GL fault");
  const GlFault* f = find_gl_fault(fault);
  if (!f || f->host) return;
  std::string upper = f->name;
  for (char& c : upper) c = char(std::toupper(static_cast<unsigned char>(c)));
  defines_ = "#define VCT_FAULT_" + upper + " 1\n";
}

std::string assemble_source(const std::string& name, const std::string& text, const std::string& defines) {
  std::vector<std::string> seen{name};
  // "#line 1 1" makes the driver's line numbers count from the top of the shader file itself
  // (source string 1), after the shared header (source string 0).
  return "#version 450\n#define VCT_GLSL 1\n" + defines + "#line 1 0\n" + embedded("vct_shared.h") + "\n#line 1 1\n" +
         expand_includes(name, text, seen, 0);
}

std::string assemble_shader(const std::string& file, const std::string& defines) {
  return assemble_source(file, embedded(file), defines);
}

ShaderSource shader_file(const std::string& file, const std::string& defines) {
  return {stage_of(file), file, assemble_shader(file, defines)};
}

Program::Program(const std::vector<ShaderSource>& stages) {
  id_ = glCreateProgram();
  std::vector<GLuint> shaders;
  for (const auto& s : stages) {
    const GLuint sh = glCreateShader(s.type);
    const char* src = s.source.c_str();
    glShaderSource(sh, 1, &src, nullptr);
    glCompileShader(sh);
    GLint ok = 0;
    glGetShaderiv(sh, GL_COMPILE_STATUS, &ok);
    if (!ok) {
      const std::string log = shader_log(sh);
      glDeleteShader(sh);
      discard_debug_errors();  // the same message is in the exception
      throw std::runtime_error("shader " + s.name + ": compile failed:\n" + log);
    }
    glAttachShader(id_, sh);
    shaders.push_back(sh);
  }
  glLinkProgram(id_);
  for (GLuint sh : shaders) glDeleteShader(sh);
  GLint ok = 0;
  glGetProgramiv(id_, GL_LINK_STATUS, &ok);
  if (!ok) {
    std::string names;
    for (const auto& s : stages) names += (names.empty() ? "" : " + ") + s.name;
    discard_debug_errors();
    throw std::runtime_error("shader program " + names + ": link failed:\n" + program_log(id_));
  }
  check_gl("program build");
}

Program Program::from_files(const std::vector<std::string>& files, const std::string& defines) {
  std::vector<ShaderSource> stages;
  for (const auto& f : files) stages.push_back(shader_file(f, defines));
  return Program(stages);
}

void Program::use() const { glUseProgram(id_); }
GLint Program::location(const char* name) const { return glGetUniformLocation(id_, name); }
void Program::set(const char* name, int v) const { glProgramUniform1i(id_, location(name), v); }
void Program::set(const char* name, unsigned v) const { glProgramUniform1ui(id_, location(name), v); }
void Program::set(const char* name, float v) const { glProgramUniform1f(id_, location(name), v); }
void Program::set(const char* name, const vec2& v) const { glProgramUniform2fv(id_, location(name), 1, &v[0]); }
void Program::set(const char* name, const vec3& v) const { glProgramUniform3fv(id_, location(name), 1, &v[0]); }
void Program::set(const char* name, const vec4& v) const { glProgramUniform4fv(id_, location(name), 1, &v[0]); }
void Program::set(const char* name, const ivec3& v) const { glProgramUniform3iv(id_, location(name), 1, &v[0]); }
void Program::set(const char* name, const mat3& v) const {
  glProgramUniformMatrix3fv(id_, location(name), 1, GL_FALSE, &v[0][0]);
}
void Program::set(const char* name, const mat4& v) const {
  glProgramUniformMatrix4fv(id_, location(name), 1, GL_FALSE, &v[0][0]);
}

}  // namespace vct::gl
