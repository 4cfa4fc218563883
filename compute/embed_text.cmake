# Writes OUTPUT: a C++ file with the text of each of FILES (paths relative to ROOT) as a raw string literal,
# and simeco::shaders::glslSource(name) to look them up.
set(body "// Generated from the GLSL sources by embed_text.cmake.\n#include <stdexcept>\n#include <string>\n#include <string_view>\n\nnamespace simeco::shaders {\n\nstd::string_view glslSource(std::string_view name) {\n")
foreach(file ${FILES})
  file(READ ${ROOT}/${file} text)
  string(FIND "${text}" ")simeco_glsl\"" clash)
  if(NOT clash EQUAL -1)
    message(FATAL_ERROR "${file} contains the raw-string delimiter")
  endif()
  string(APPEND body "    if (name == \"${file}\") return R\"simeco_glsl(${text})simeco_glsl\";\n")
endforeach()
string(APPEND body "    throw std::out_of_range(\"no embedded GLSL source \" + std::string(name));\n}\n\n} // namespace simeco::shaders\n")
file(WRITE ${OUTPUT} "${body}")
