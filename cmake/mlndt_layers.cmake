# The library's layers (KISS-ICP's core/metrics/pipeline is the model): each
# is an OBJECT library over some of mlndt/'s module folders, and the
# installed static library mlndt is their objects together, so users see one
# target, mlndt::mlndt, as before.
#
# A layer may call only into itself and the layers below it. The build
# checks that by linking each layer once more, as a shared object in
# build/layer_check/, with -Wl,--no-undefined and only the layers it
# declares (and Ceres, glog, OpenMP, lzf): a call from a lower layer into a
# higher one is an undefined symbol there, and the build fails. mlndt
# depends on these checks, so every build of the library runs them.
# scripts/check_boundaries.sh checks the same order on the includes (which
# also catches a wrong-way include of inline or template code only).

# Off only for toolchains whose shared objects cannot resolve everything at
# link time (clang's sanitizers link their runtime into executables only).
option(MLNDT_CHECK_LAYERS "Fail the build when a layer of mlndt calls a layer above it" ON)

set(MLNDT_LAYERS)
set(MLNDT_LAYER_SOURCES)

# mlndt_add_layer(NAME FOLDERS folder... [DEPENDS layer...]): the layer
# mlndt_NAME over mlndt/<folder>/**.cc, which may call the layers DEPENDS.
function(mlndt_add_layer name)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "" "FOLDERS;DEPENDS")
  set(sources)
  foreach(folder IN LISTS arg_FOLDERS)
    file(GLOB_RECURSE folder_sources CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/mlndt/${folder}/*.cc)
    list(APPEND sources ${folder_sources})
  endforeach()
  set(target mlndt_${name})
  add_library(${target} OBJECT ${sources})
  target_include_directories(${target} PUBLIC $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}>)
  target_include_directories(${target} PRIVATE ${LZF_INCLUDE_DIR})
  target_link_libraries(${target}
    PUBLIC Eigen3::Eigen Ceres::ceres glog::glog
    PRIVATE OpenMP::OpenMP_CXX)
  target_compile_options(${target} PRIVATE -Wall -Wextra)

  if(MLNDT_CHECK_LAYERS)
    set(check ${target}_layer_check)
    add_library(${check} SHARED $<TARGET_OBJECTS:${target}>)
    set_target_properties(${check} PROPERTIES
      LINKER_LANGUAGE CXX
      LIBRARY_OUTPUT_DIRECTORY ${PROJECT_BINARY_DIR}/layer_check)
    target_link_options(${check} PRIVATE LINKER:--no-undefined)
    list(TRANSFORM arg_DEPENDS APPEND _layer_check OUTPUT_VARIABLE below)
    list(TRANSFORM below PREPEND mlndt_)
    target_link_libraries(${check} PRIVATE ${below}
      Ceres::ceres glog::glog OpenMP::OpenMP_CXX ${LZF_LIBRARY})
  endif()

  set(MLNDT_LAYERS ${MLNDT_LAYERS} ${name} PARENT_SCOPE)
  set(MLNDT_LAYER_SOURCES ${MLNDT_LAYER_SOURCES} ${sources} PARENT_SCOPE)
endfunction()

# mlndt_check_layers_cover(): fails the configuration when a .cc under
# mlndt/ is in no layer (a new module folder must be given one).
function(mlndt_check_layers_cover)
  file(GLOB_RECURSE all CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/mlndt/*.cc)
  list(REMOVE_ITEM all ${MLNDT_LAYER_SOURCES})
  if(all)
    message(FATAL_ERROR "mlndt: in no layer (cmake/mlndt_layers.cmake, CMakeLists.txt): ${all}")
  endif()
endfunction()
