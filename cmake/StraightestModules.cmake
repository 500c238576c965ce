# The core's modules, one static library each (core/<module>/src, public headers in
# core/<module>/include/straightest/<module>/). A module links only the modules below it, so a header
# of a module above is not on its include path: a wrong-way #include fails to compile.
#
#   base ← mesh ← io
#   base ← solver
#   mesh ← paths ← geodesics
#   mesh ← cut
#   geodesics, cut, solver ← param ← atlas
#   atlas, io ← api
#
# straightest_add_core(<suffix> [compile options...]) defines straightest_<module><suffix> for every
# module and straightest_core<suffix>, an INTERFACE library of them all (what programs link). The
# suffix lets one build compile the core twice (the threaded WASM module, the CGAL benchmark's copy).
set(STRAIGHTEST_MODULES base mesh io solver paths geodesics cut param atlas api)
set(STRAIGHTEST_DEPS_base "")
set(STRAIGHTEST_DEPS_mesh base)
set(STRAIGHTEST_DEPS_io mesh)
set(STRAIGHTEST_DEPS_solver base)
set(STRAIGHTEST_DEPS_paths mesh)
set(STRAIGHTEST_DEPS_geodesics paths)
set(STRAIGHTEST_DEPS_cut mesh)
set(STRAIGHTEST_DEPS_param geodesics cut solver)
set(STRAIGHTEST_DEPS_atlas param)
set(STRAIGHTEST_DEPS_api atlas io)
set(STRAIGHTEST_CORE_DIR ${CMAKE_CURRENT_LIST_DIR}/../core)
get_filename_component(STRAIGHTEST_CORE_DIR ${STRAIGHTEST_CORE_DIR} ABSOLUTE)

function(straightest_add_core suffix)
  set(options ${ARGN})
  foreach(module IN LISTS STRAIGHTEST_MODULES)
    set(target straightest_${module}${suffix})
    file(GLOB_RECURSE sources CONFIGURE_DEPENDS ${STRAIGHTEST_CORE_DIR}/${module}/src/*.cpp)
    add_library(${target} STATIC ${sources})
    set_target_properties(${target} PROPERTIES EXPORT_NAME ${module} OUTPUT_NAME straightest_${module}${suffix})
    target_include_directories(${target} PUBLIC $<BUILD_INTERFACE:${STRAIGHTEST_CORE_DIR}/${module}/include>
                                                $<INSTALL_INTERFACE:include>)
    if(STRAIGHTEST_THIRD_PARTY_INCLUDE)  # fast_float, copied where the WASM builds may read it
      target_include_directories(${target} SYSTEM PRIVATE ${STRAIGHTEST_THIRD_PARTY_INCLUDE})
    endif()
    target_compile_options(${target} PRIVATE ${options})
    foreach(dep IN LISTS STRAIGHTEST_DEPS_${module})
      target_link_libraries(${target} PUBLIC straightest_${dep}${suffix})
    endforeach()
  endforeach()
  # Eigen stays private: no public header includes it. The solver's bridge to it is shared with SLIM's
  # global step (param) through an include path of its own, never installed.
  target_link_libraries(straightest_solver${suffix} PRIVATE Eigen3::Eigen)
  target_link_libraries(straightest_param${suffix} PRIVATE Eigen3::Eigen)
  target_link_libraries(straightest_geodesics${suffix} PRIVATE Eigen3::Eigen)
  foreach(module solver param)
    target_include_directories(straightest_${module}${suffix} PRIVATE
                               $<BUILD_INTERFACE:${STRAIGHTEST_CORE_DIR}/solver/internal>)
  endforeach()
  add_library(straightest_core${suffix} INTERFACE)
  foreach(module IN LISTS STRAIGHTEST_MODULES)
    target_link_libraries(straightest_core${suffix} INTERFACE straightest_${module}${suffix})
  endforeach()
endfunction()
