# ctest's cmake_consumer: installs the build into a fresh prefix, then configures, builds and runs the
# consumer project against it (what a C++ user does with find_package(straightest)).
set(prefix ${BUILD_DIR}/consumer/prefix)
file(REMOVE_RECURSE ${BUILD_DIR}/consumer)
foreach(step
    "${CMAKE_COMMAND};--install;${BUILD_DIR};--prefix;${prefix}"
    "${CMAKE_COMMAND};-S;${SOURCE_DIR}/tests/cmake-consumer;-B;${BUILD_DIR}/consumer/build;-DCMAKE_PREFIX_PATH=${prefix};-DCMAKE_BUILD_TYPE=Release"
    "${CMAKE_COMMAND};--build;${BUILD_DIR}/consumer/build"
    "${BUILD_DIR}/consumer/build/flatten;${SOURCE_DIR}/tests/data/good/quad_grid.obj;${BUILD_DIR}/consumer/out.obj")
  execute_process(COMMAND ${step} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${step} failed (${rc}):\n${out}\n${err}")
  endif()
endforeach()
message(STATUS "${out}")
if(NOT out MATCHES "paths reached, stretch L2 1\\.[0-9]+")
  message(FATAL_ERROR "unexpected output: ${out}")
endif()
file(STRINGS ${BUILD_DIR}/consumer/out.obj vt REGEX "^vt ")
list(LENGTH vt count)
if(count EQUAL 0)
  message(FATAL_ERROR "the OBJ has no vt lines")
endif()
