# Build-time script: writes a .cc whose one function returns a text file's
# contents, so a binary carries its data files (the catalogue, name maps).
#   cmake -DIN=<text file> -DOUT=<generated .cc> -DFUNCTION=<C++ function name>
#         -DHEADER=<header declaring it> -P cmake/embed_text.cmake
# The function is `const char* FUNCTION()` in namespace bespoke.
file(READ "${IN}" content)
string(FIND "${content}" ")embedded_text\"" clash)
if(NOT clash EQUAL -1)
  message(FATAL_ERROR "${IN} contains the raw-string delimiter )embedded_text\"")
endif()
file(WRITE "${OUT}.tmp"
  "// Generated from ${IN} by cmake/embed_text.cmake. Do not edit.\n"
  "#include \"${HEADER}\"\n"
  "namespace bespoke {\n"
  "const char* ${FUNCTION}() {\n"
  "  return R\"embedded_text(${content})embedded_text\";\n"
  "}\n"
  "}  // namespace bespoke\n")
file(COPY_FILE "${OUT}.tmp" "${OUT}" ONLY_IF_DIFFERENT)
file(REMOVE "${OUT}.tmp")
