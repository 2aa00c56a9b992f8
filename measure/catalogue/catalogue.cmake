# Compiles measure/catalogue/catalogue.json into bespoke_catalogue (included
# from measure/catalogue/CMakeLists.txt after the library is declared). The JSON is
# re-embedded whenever it changes, without re-running CMake.
set(_bespoke_catalogue_json ${CMAKE_CURRENT_SOURCE_DIR}/catalogue.json)
set(_bespoke_catalogue_cc ${CMAKE_CURRENT_BINARY_DIR}/catalogue_json.cc)
add_custom_command(
  OUTPUT ${_bespoke_catalogue_cc}
  COMMAND ${CMAKE_COMMAND} -DIN=${_bespoke_catalogue_json} -DOUT=${_bespoke_catalogue_cc}
          -DFUNCTION=BuiltinCatalogueJson -DHEADER=measure/catalogue/catalogue.h
          -P ${PROJECT_SOURCE_DIR}/cmake/embed_text.cmake
  DEPENDS ${_bespoke_catalogue_json} ${PROJECT_SOURCE_DIR}/cmake/embed_text.cmake
  COMMENT "Embedding the measurement catalogue"
  VERBATIM)
target_sources(bespoke_catalogue PRIVATE ${_bespoke_catalogue_cc})
