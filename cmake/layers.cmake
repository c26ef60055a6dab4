# The layers of src/ (docs/architecture.md § Layers), checked two ways:
#  - every header compiles on its own (libosmium's BUILD_HEADERS): one generated translation unit per
#    header, `#include "x/y.h"` and nothing else, compiled with the project's warnings, so that a header
#    leaning on what its includer happened to include first fails here and not in the next edit;
#  - scripts/check_layers.py fails on an include against the layer order or on an include cycle, and
#    its self-test makes sure it still can fail.

option(URBIS_HEADER_CHECK "Compile every header of src/ alone (one generated translation unit each)"
       ${URBIS_BUILD_TESTS})

if(URBIS_HEADER_CHECK)
  # The device side of gpu/ includes the CUDA runtime: nvcc compiles those, with the kernels' flags.
  set(URBIS_CUDA_ONLY_HEADERS "^gpu/(device_[^/]*|cuda_check|pinned_buffer)\\.h$")
  set(urbis_header_units_dir "${CMAKE_CURRENT_BINARY_DIR}/header_check")
  file(GLOB_RECURSE urbis_headers CONFIGURE_DEPENDS RELATIVE "${CMAKE_CURRENT_SOURCE_DIR}/src"
       "${CMAKE_CURRENT_SOURCE_DIR}/src/*.h")
  set(urbis_host_header_units "")
  set(urbis_cuda_header_units "")
  foreach(header IN LISTS urbis_headers)
    if(header MATCHES "${URBIS_CUDA_ONLY_HEADERS}")
      if(NOT URBIS_HAVE_CUDA)
        continue()
      endif()
      set(unit "${urbis_header_units_dir}/${header}.cu")
      list(APPEND urbis_cuda_header_units "${unit}")
    else()
      set(unit "${urbis_header_units_dir}/${header}.cpp")
      list(APPEND urbis_host_header_units "${unit}")
    endif()
    # Written only when the text changes, so a configure does not rebuild every unit.
    file(CONFIGURE OUTPUT "${unit}" CONTENT "#include \"${header}\"\n" @ONLY)
  endforeach()

  add_library(urbis_header_check OBJECT ${urbis_host_header_units})
  target_compile_options(urbis_header_check PRIVATE ${URBIS_WARNINGS})
  target_link_libraries(urbis_header_check PRIVATE urbis_core)   # its include paths and definitions

  if(urbis_cuda_header_units)
    add_library(urbis_header_check_cuda OBJECT ${urbis_cuda_header_units})
    set_target_properties(urbis_header_check_cuda PROPERTIES CUDA_STANDARD 20 CUDA_STANDARD_REQUIRED ON
      CUDA_EXTENSIONS OFF)
    # urbis_gpu's flags and definitions, not the target itself: these units need not wait for the kernels.
    target_compile_options(urbis_header_check_cuda PRIVATE $<TARGET_PROPERTY:urbis_gpu,COMPILE_OPTIONS>)
    target_compile_definitions(urbis_header_check_cuda PRIVATE
      $<TARGET_PROPERTY:urbis_gpu,INTERFACE_COMPILE_DEFINITIONS>)
    target_link_libraries(urbis_header_check_cuda PRIVATE urbis_core CUDA::cudart_static)
    add_dependencies(urbis_header_check urbis_header_check_cuda)
  endif()
endif()

if(URBIS_BUILD_TESTS)
  find_package(Python3 REQUIRED COMPONENTS Interpreter)
  add_test(NAME layers COMMAND "${Python3_EXECUTABLE}" scripts/check_layers.py src
           WORKING_DIRECTORY "${CMAKE_CURRENT_SOURCE_DIR}")
  add_test(NAME layers_self_test
           COMMAND "${Python3_EXECUTABLE}" scripts/check_layers.py tests/layers_fixture/src
                   --expect tests/layers_fixture/expected.txt
           WORKING_DIRECTORY "${CMAKE_CURRENT_SOURCE_DIR}")
  if(URBIS_HEADER_CHECK)
    # The headers are part of the default build; this names the check among the tests and builds it
    # where only the test programs were built.
    add_test(NAME headers_compile_alone
             COMMAND "${CMAKE_COMMAND}" --build "${CMAKE_BINARY_DIR}" --target urbis_header_check
                     --config $<CONFIG>)
  endif()
endif()
