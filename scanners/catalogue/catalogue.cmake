# Compiles scanners/catalogue/catalogue.json into bespoke_scanners (included
# from scanners/CMakeLists.txt after the library is declared). The JSON is
# re-embedded whenever it changes, without re-running CMake.
set(_bespoke_catalogue_json ${CMAKE_CURRENT_SOURCE_DIR}/catalogue/catalogue.json)
set(_bespoke_catalogue_cc ${CMAKE_CURRENT_BINARY_DIR}/catalogue/catalogue_json.cc)
add_custom_command(
  OUTPUT ${_bespoke_catalogue_cc}
  COMMAND ${CMAKE_COMMAND} -DIN=${_bespoke_catalogue_json} -DOUT=${_bespoke_catalogue_cc}
          -P ${CMAKE_CURRENT_SOURCE_DIR}/catalogue/embed_json.cmake
  DEPENDS ${_bespoke_catalogue_json} ${CMAKE_CURRENT_SOURCE_DIR}/catalogue/embed_json.cmake
  COMMENT "Embedding the measurement catalogue"
  VERBATIM)
target_sources(bespoke_scanners PRIVATE ${_bespoke_catalogue_cc})
