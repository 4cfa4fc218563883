# How both shader roots (compute/ and render/) are built: one function per root, one registry for all.
#
# simeco_add_shaders(ROOT SHADERS ... HEADERS ... [RUNTIME_GLSL ...]) compiles each shader of the root with
# glslangValidator at build time (one custom command each, output in the build tree, never in the source tree;
# every shader is rebuilt when a header changes), turns the SPIR-V into a .cpp holding a uint32_t array
# (embed_spirv.cmake), and keeps RUNTIME_GLSL sources as text for the kernels generated at run time
# (embed_text.cmake). Shaders include every file by its path from the repository root
# ("compute/shared/random.h"). A shader's name is its path under its root, without the `.comp` of a compute
# kernel: "scan/reduce", "organs/organ.vert".
#
# simeco_shader_library(TARGET) then makes the library that holds every root's shaders and the registry that
# looks them up by name (compute/shaders.h).

set(SIMECO_SHADER_CMAKE_DIR ${CMAKE_CURRENT_LIST_DIR})

function(simeco_add_shaders root)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "" "SHADERS;HEADERS;RUNTIME_GLSL")
  set(root_dir ${CMAKE_SOURCE_DIR}/${root})
  set(spirv_dir ${CMAKE_CURRENT_BINARY_DIR}/spirv)
  set(headers ${arg_HEADERS})
  list(TRANSFORM headers PREPEND ${root_dir}/)
  list(APPEND headers ${CMAKE_SOURCE_DIR}/compute/shared/preamble.h)
  set(embedded_sources)
  get_property(declarations GLOBAL PROPERTY SIMECO_SHADER_DECLARATIONS)
  get_property(entries GLOBAL PROPERTY SIMECO_SHADER_ENTRIES)
  get_property(names GLOBAL PROPERTY SIMECO_SHADER_NAMES)

  foreach(shader ${arg_SHADERS})
    string(REGEX REPLACE "\\.comp$" "" name ${shader})
    if(name IN_LIST names)
      message(FATAL_ERROR "two shaders are named '${name}'")
    endif()
    list(APPEND names ${name})
    string(MAKE_C_IDENTIFIER "${root}_${name}" symbol)
    set(source ${root_dir}/${shader})
    set(spv ${spirv_dir}/${symbol}.spv)
    set(embedded ${spirv_dir}/${symbol}.cpp)

    add_custom_command(
      OUTPUT ${spv}
      COMMAND ${CMAKE_COMMAND} -E make_directory ${spirv_dir}
      COMMAND ${GLSLANG_VALIDATOR} -V --target-env vulkan1.2 -I${CMAKE_SOURCE_DIR} -o ${spv} ${source}
      DEPENDS ${source} ${headers}
      COMMENT "Compiling shader ${root}/${shader}"
      VERBATIM)
    add_custom_command(
      OUTPUT ${embedded}
      COMMAND ${CMAKE_COMMAND} -DSPIRV=${spv} -DOUTPUT=${embedded} -DSYMBOL=${symbol}
              -P ${SIMECO_SHADER_CMAKE_DIR}/embed_spirv.cmake
      DEPENDS ${spv} ${SIMECO_SHADER_CMAKE_DIR}/embed_spirv.cmake
      COMMENT "Embedding shader ${root}/${shader}"
      VERBATIM)
    list(APPEND embedded_sources ${embedded})
    string(APPEND declarations "extern const std::uint32_t ${symbol}[];\nextern const std::size_t ${symbol}_words;\n")
    string(APPEND entries "    {\"${name}\", {${symbol}, ${symbol}_words}},\n")
  endforeach()

  if(arg_RUNTIME_GLSL)
    set(text_source ${spirv_dir}/${root}_glsl_sources.cpp)
    set(runtime_paths ${arg_RUNTIME_GLSL})
    list(TRANSFORM runtime_paths PREPEND ${root_dir}/)
    add_custom_command(
      OUTPUT ${text_source}
      COMMAND ${CMAKE_COMMAND} -DROOT=${CMAKE_SOURCE_DIR} -DPREFIX=${root}/ "-DFILES=${arg_RUNTIME_GLSL}"
              -DOUTPUT=${text_source} -P ${SIMECO_SHADER_CMAKE_DIR}/embed_text.cmake
      DEPENDS ${runtime_paths} ${SIMECO_SHADER_CMAKE_DIR}/embed_text.cmake
      COMMENT "Embedding the GLSL sources of run-time kernels from ${root}/"
      VERBATIM)
    list(APPEND embedded_sources ${text_source})
    string(MAKE_C_IDENTIFIER "embeddedGlslText_${root}/" text_function)
    set_property(GLOBAL APPEND PROPERTY SIMECO_SHADER_TEXT_FUNCTIONS ${text_function})
  endif()

  add_library(simeco_shaders_${root} OBJECT ${embedded_sources})
  target_compile_features(simeco_shaders_${root} PUBLIC cxx_std_20)
  set_property(GLOBAL APPEND PROPERTY SIMECO_SHADER_ROOTS ${root})
  set_property(GLOBAL PROPERTY SIMECO_SHADER_DECLARATIONS "${declarations}")
  set_property(GLOBAL PROPERTY SIMECO_SHADER_ENTRIES "${entries}")
  set_property(GLOBAL PROPERTY SIMECO_SHADER_NAMES "${names}")
endfunction()

function(simeco_shader_library target)
  get_property(roots GLOBAL PROPERTY SIMECO_SHADER_ROOTS)
  get_property(registry_declarations GLOBAL PROPERTY SIMECO_SHADER_DECLARATIONS)
  get_property(registry_entries GLOBAL PROPERTY SIMECO_SHADER_ENTRIES)
  get_property(text_functions GLOBAL PROPERTY SIMECO_SHADER_TEXT_FUNCTIONS)
  set(text_declarations "")
  set(text_lookups "")
  foreach(function ${text_functions})
    string(APPEND text_declarations "std::optional<std::string_view> ${function}(std::string_view name);\n")
    string(APPEND text_lookups "    if (auto text = ${function}(name)) return text;\n")
  endforeach()
  set(registry ${CMAKE_CURRENT_BINARY_DIR}/shaders_registry.cpp)
  configure_file(${SIMECO_SHADER_CMAKE_DIR}/shaders_registry.cpp.in ${registry} @ONLY)
  set(objects)
  foreach(root ${roots})
    list(APPEND objects $<TARGET_OBJECTS:simeco_shaders_${root}>)
  endforeach()
  add_library(${target} STATIC ${registry} ${SIMECO_SHADER_CMAKE_DIR}/glsl_includes.cpp ${objects})
  # Users include "compute/shaders.h" and the shared layouts by their path from the repository root.
  target_include_directories(${target} PUBLIC ${CMAKE_SOURCE_DIR})
  target_compile_features(${target} PUBLIC cxx_std_20)
endfunction()
