# Writes a C++ file defining vct::embedded_scene(name) over the given FILES (self-contained glTF
# text), so the binary carries its built-in scene. Same pattern as EmbedFiles.cmake (shaders).
set(body "#include <map>\n#include <string>\n#include \"scene/embedded_scenes.h\"\nnamespace vct {\nconst std::string& embedded_scene(const std::string& name) {\n  static const std::map<std::string, std::string> files = {\n")
foreach(f ${FILES})
  get_filename_component(name ${f} NAME)
  file(READ ${f} content)
  set(body "${body}    {\"${name}\", R\"vct_scene(${content})vct_scene\"},\n")
endforeach()
set(body "${body}  };\n  static const std::string none;\n  auto it = files.find(name);\n  return it == files.end() ? none : it->second;\n}\n}  // namespace vct\n")
file(WRITE ${OUT}.tmp "${body}")
file(RENAME ${OUT}.tmp ${OUT})
