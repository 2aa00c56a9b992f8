# Build-time script: writes a .cc that returns the catalogue file's text.
#   cmake -DIN=<catalogue.json> -DOUT=<generated .cc> -P embed_json.cmake
file(READ "${IN}" content)
string(FIND "${content}" ")catalogue_json\"" clash)
if(NOT clash EQUAL -1)
  message(FATAL_ERROR "${IN} contains the raw-string delimiter )catalogue_json\"")
endif()
file(WRITE "${OUT}.tmp"
  "// Generated from ${IN} by measure/catalogue/embed_json.cmake. Do not edit.\n"
  "#include \"measure/catalogue/catalogue.h\"\n"
  "namespace bespoke {\n"
  "const char* BuiltinCatalogueJson() {\n"
  "  return R\"catalogue_json(${content})catalogue_json\";\n"
  "}\n"
  "}  // namespace bespoke\n")
file(COPY_FILE "${OUT}.tmp" "${OUT}" ONLY_IF_DIFFERENT)
file(REMOVE "${OUT}.tmp")
