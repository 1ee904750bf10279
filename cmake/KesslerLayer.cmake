# kessler_layer(NAME DEPENDS dep... EXTERNAL lib...) builds src/NAME/**.cpp into the library
# kessler_NAME. A layer with headers only (or not yet any sources) becomes an interface library.
function(kessler_layer name)
  cmake_parse_arguments(arg "" "" "DEPENDS;EXTERNAL" ${ARGN})
  file(GLOB_RECURSE sources CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/*.cpp)
  if(sources)
    add_library(kessler_${name} STATIC ${sources})
    target_link_libraries(kessler_${name} PUBLIC kessler_options ${arg_DEPENDS} ${arg_EXTERNAL})
  else()
    add_library(kessler_${name} INTERFACE)
    target_link_libraries(kessler_${name} INTERFACE kessler_options ${arg_DEPENDS} ${arg_EXTERNAL})
  endif()
endfunction()
