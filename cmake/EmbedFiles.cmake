# Writes a C++ file defining `const std::map<std::string, std::string>& NAMESPACE::FUNCTION()`,
# file name -> content, over the given FILES, so the binary carries them (shaders, the built-in
# scene) with no run-time lookup of a source folder.
#   cmake -DOUT=x.cpp -DFILES="a;b" -DNAMESPACE=vct::gl -DFUNCTION=embedded_files -P EmbedFiles.cmake
set(body "#include <map>\n#include <string>\nnamespace ${NAMESPACE} {\nconst std::map<std::string, std::string>& ${FUNCTION}() {\n  static const std::map<std::string, std::string> files = {\n")
foreach(f ${FILES})
  get_filename_component(name ${f} NAME)
  file(READ ${f} content)
  set(body "${body}    {\"${name}\", R\"vct_embed(${content})vct_embed\"},\n")
endforeach()
set(body "${body}  };\n  return files;\n}\n}  // namespace ${NAMESPACE}\n")
file(WRITE ${OUT}.tmp "${body}")
file(RENAME ${OUT}.tmp ${OUT})
