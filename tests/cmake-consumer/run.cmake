# ctest's cmake_consumer: installs the build into a fresh prefix, then configures, builds and runs the
# consumer project against it (what a C++ user does with find_package(straightest)). Its program is the
# README's C++ example, taken from README.md as written, so the example cannot drift from what works.
set(prefix ${BUILD_DIR}/consumer/prefix)
set(project ${BUILD_DIR}/consumer/project)
file(REMOVE_RECURSE ${BUILD_DIR}/consumer)
file(READ ${SOURCE_DIR}/README.md readme)
if(NOT readme MATCHES "```cpp\n([^`]*)```")
  message(FATAL_ERROR "README.md has no ```cpp block")
endif()
file(WRITE ${project}/main.cpp "${CMAKE_MATCH_1}")
configure_file(${SOURCE_DIR}/tests/cmake-consumer/CMakeLists.txt ${project}/CMakeLists.txt COPYONLY)
foreach(step
    "${CMAKE_COMMAND};--install;${BUILD_DIR};--prefix;${prefix}"
    "${CMAKE_COMMAND};-S;${project};-B;${BUILD_DIR}/consumer/build;-DCMAKE_PREFIX_PATH=${prefix};-DCMAKE_BUILD_TYPE=Release"
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
