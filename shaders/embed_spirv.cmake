# Turns a SPIR-V binary into a C++ source holding it as a uint32_t array:
#   cmake -DINPUT=x.spv -DOUTPUT=x.cpp -DSYMBOL=name -P embed_spirv.cmake
# defines  extern const uint32_t quadtri::shaders::<SYMBOL>[];  and  <SYMBOL>_words.
foreach(var INPUT OUTPUT SYMBOL)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "embed_spirv.cmake: ${var} not set")
  endif()
endforeach()
file(READ "${INPUT}" hex HEX)
string(LENGTH "${hex}" nhex)
math(EXPR rem "${nhex} % 8")
if(nhex EQUAL 0 OR NOT rem EQUAL 0)
  message(FATAL_ERROR "embed_spirv.cmake: ${INPUT} is not a SPIR-V binary (size not a multiple of 4)")
endif()
# SPIR-V is little-endian words: reverse the bytes of each 8-hex-digit group.
string(REGEX REPLACE "(..)(..)(..)(..)" "0x\\4\\3\\2\\1u;" list "${hex}")
set(words "")
set(n 0)
foreach(w IN LISTS list)
  if(w STREQUAL "")
    continue()
  endif()
  math(EXPR col "${n} % 8")
  if(n GREATER 0 AND col EQUAL 0)
    string(APPEND words "\n    ")
  endif()
  string(APPEND words "${w}, ")
  math(EXPR n "${n} + 1")
endforeach()
math(EXPR nwords "${nhex} / 8")
file(WRITE "${OUTPUT}.tmp"
"// Generated from ${INPUT} by shaders/embed_spirv.cmake: do not edit.
#include <cstddef>
#include <cstdint>

namespace quadtri {
inline namespace v0 {
namespace shaders {
extern const uint32_t ${SYMBOL}[];
extern const std::size_t ${SYMBOL}_words;
const uint32_t ${SYMBOL}[] = {
    ${words}
};
const std::size_t ${SYMBOL}_words = ${nwords};
}  // namespace shaders
}  // namespace v0
}  // namespace quadtri
")
file(COPY_FILE "${OUTPUT}.tmp" "${OUTPUT}" ONLY_IF_DIFFERENT)
file(REMOVE "${OUTPUT}.tmp")
