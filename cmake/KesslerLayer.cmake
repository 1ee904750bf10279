# kessler_layer(NAME DEPENDS dep...) builds src/NAME/**.cpp into the library kessler_NAME.
function(kessler_layer name)
  cmake_parse_arguments(arg "" "" "DEPENDS;EXTERNAL" ${ARGN})
  file(GLOB_RECURSE sources CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/*.cpp)
  add_library(kessler_${name} STATIC ${sources})
  target_link_libraries(kessler_${name} PUBLIC kessler_options ${arg_DEPENDS} ${arg_EXTERNAL})
endfunction()
