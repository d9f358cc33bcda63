# Writes a C++ file defining vct::gl::embedded_file(name) over the given FILES, so the binary
# carries its shaders (no run-time lookup of a source folder).
set(body "#include <map>\n#include <string>\nnamespace vct { namespace gl {\nconst std::map<std::string, std::string>& embedded_files() {\n  static const std::map<std::string, std::string> files = {\n")
foreach(f ${FILES})
  get_filename_component(name ${f} NAME)
  file(READ ${f} content)
  set(body "${body}    {\"${name}\", R\"vct_embed(${content})vct_embed\"},\n")
endforeach()
set(body "${body}  };\n  return files;\n}\n}  // namespace gl\n}  // namespace vct\n")
file(WRITE ${OUT}.tmp "${body}")
file(RENAME ${OUT}.tmp ${OUT})
