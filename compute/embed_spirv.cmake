# Turns a SPIR-V binary into a C++ source defining `const std::uint32_t SYMBOL[]` and `SYMBOL_words`.
# Usage: cmake -DSPIRV=in.spv -DOUTPUT=out.cpp -DSYMBOL=name -P embed_spirv.cmake
# SPIR-V is a stream of little-endian 32-bit words, so each group of 4 bytes is reversed into one literal.

file(READ ${SPIRV} hex HEX)
string(LENGTH "${hex}" hex_length)
math(EXPR remainder "${hex_length} % 8")
if(hex_length EQUAL 0 OR NOT remainder EQUAL 0)
  message(FATAL_ERROR "${SPIRV}: not a SPIR-V binary (size is not a positive multiple of 4 bytes)")
endif()
math(EXPR word_count "${hex_length} / 8")

string(REGEX REPLACE "(..)(..)(..)(..)" "0x\\4\\3\\2\\1u," words "${hex}")
# Eight words per line keeps the generated file readable in a debugger.
string(REGEX REPLACE "((0x[0-9a-f]+u,){8})" "\\1\n    " words "${words}")

file(WRITE ${OUTPUT} "// Generated from ${SPIRV} by embed_spirv.cmake; do not edit.
#include <cstddef>
#include <cstdint>

extern const std::uint32_t ${SYMBOL}[] = {
    ${words}
};
extern const std::size_t ${SYMBOL}_words = ${word_count};
")
