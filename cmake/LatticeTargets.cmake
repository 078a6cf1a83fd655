# lattice_add_library(NAME DEPS...): a static library from the .cpp files of
# the calling folder and its sub-folders (an INTERFACE library while a folder
# has only headers). One library per top folder (a layer, docs/architecture.md)
# keeps "find the concept by its folder" true in the build; the sub-folders
# name the ideas inside a layer (render/shapes, lht/table, ...).
function(lattice_add_library name)
  file(GLOB_RECURSE sources CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/*.cpp)
  if(sources)
    add_library(${name} STATIC ${sources})
    target_link_libraries(${name} PUBLIC ${ARGN} PRIVATE lattice_warnings)
  else()
    add_library(${name} INTERFACE)
    target_link_libraries(${name} INTERFACE ${ARGN})
  endif()
endfunction()
