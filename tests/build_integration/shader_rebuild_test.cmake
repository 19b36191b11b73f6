# A project using iblkit_add_shader rebuilds its SPIR-V when a header the shader includes
# changes, and only then. Run with -DIBLKIT=<iblkit executable> -DSOURCE_DIR=<repository>
# -DWORK_DIR=<scratch folder> -DMAKE_PROGRAM=<ninja>.
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR}/project/Common)
file(WRITE ${WORK_DIR}/project/Common/Value.fxh "static const float Value = 1.0f;\n")
file(WRITE ${WORK_DIR}/project/Fill.hlsl "#include \"Common/Value.fxh\"\nRWTexture2D<float4> Target;\n[numthreads(8, 8, 1)]\nvoid main(uint3 id : SV_DispatchThreadID) { Target[id.xy] = Value; }\n")
file(WRITE ${WORK_DIR}/project/CMakeLists.txt "
cmake_minimum_required(VERSION 3.25)
project(uses_iblkit NONE)
add_executable(iblkit::cli IMPORTED)
set_target_properties(iblkit::cli PROPERTIES IMPORTED_LOCATION ${IBLKIT})
include(${SOURCE_DIR}/tools/cmake/IblkitShaders.cmake)
iblkit_add_shader(Fill SOURCE \${CMAKE_CURRENT_SOURCE_DIR}/Fill.hlsl INCLUDE_DIRS \${CMAKE_CURRENT_SOURCE_DIR})
add_custom_target(shaders ALL DEPENDS \${CMAKE_BINARY_DIR}/shaders/Fill.spv)
")

include(${CMAKE_CURRENT_LIST_DIR}/../support/run_step.cmake)

function(expect_rebuild expected what)
  run(${MAKE_PROGRAM} -C ${WORK_DIR}/build -n)
  string(FIND "${output}" "iblkit compile Fill" found)
  if(expected AND found EQUAL -1)
    message(FATAL_ERROR "${what}: the shader was not going to be rebuilt:\n${output}")
  elseif(NOT expected AND NOT found EQUAL -1)
    message(FATAL_ERROR "${what}: the shader was going to be rebuilt needlessly:\n${output}")
  endif()
endfunction()

run(${CMAKE_COMMAND} -S ${WORK_DIR}/project -B ${WORK_DIR}/build -G Ninja -DCMAKE_MAKE_PROGRAM=${MAKE_PROGRAM})
run(${MAKE_PROGRAM} -C ${WORK_DIR}/build)
if(NOT EXISTS ${WORK_DIR}/build/shaders/Fill.spv OR NOT EXISTS ${WORK_DIR}/build/shaders/Fill.json)
  message(FATAL_ERROR "the build wrote no Fill.spv and Fill.json")
endif()
expect_rebuild(FALSE "right after a build")
# Ninja compares modification times; make sure the header's is newer than the output's.
execute_process(COMMAND ${CMAKE_COMMAND} -E sleep 1.1)
file(TOUCH ${WORK_DIR}/project/Common/Value.fxh)
expect_rebuild(TRUE "after the included header changed")
run(${MAKE_PROGRAM} -C ${WORK_DIR}/build)
expect_rebuild(FALSE "after rebuilding")
file(REMOVE_RECURSE ${WORK_DIR})
