# The kit as another project uses it: `cmake --install` into a scratch prefix; examples/consumer
# configured against that prefix alone (find_package(iblkit)), built (its shader compiled by the
# installed iblkit_add_shader) and run; and a program built from the pkg-config file.
# Run with -DBUILD_DIR=<the kit's build> -DSOURCE_DIR=<repository> -DWORK_DIR=<scratch folder>
# -DMAKE_PROGRAM=<ninja> -DCXX=<compiler>.
include(${CMAKE_CURRENT_LIST_DIR}/../support/run_step.cmake)
file(REMOVE_RECURSE ${WORK_DIR})
set(prefix ${WORK_DIR}/prefix)
run(${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})
expect_files(${prefix} bin/iblkit include/iblkit/iblkit.hpp lib/cmake/iblkit/iblkitConfig.cmake
             lib/cmake/iblkit/iblkitConfigVersion.cmake lib/cmake/iblkit/IblkitShaders.cmake lib/pkgconfig/iblkit.pc
             share/iblkit/hlsl/document/Common/PBR.fxh)
file(GLOB library ${prefix}/lib/libiblkit.so.*)
if(NOT library)
  message(FATAL_ERROR "no libiblkit.so.* under ${prefix}/lib")
endif()
# Only the public headers: an internal one would need the kit's sources to compile.
file(GLOB_RECURSE headers RELATIVE ${prefix}/include ${prefix}/include/*)
foreach(header IN LISTS headers)
  if(NOT header MATCHES "^iblkit/[a-z_]+\\.hpp$")
    message(FATAL_ERROR "installed a header that is not of the public API: include/${header}")
  endif()
endforeach()

# The consumer sees the prefix alone: no package registry, no source or build tree of the kit.
set(consumer ${WORK_DIR}/consumer)
run(${CMAKE_COMMAND} -S ${SOURCE_DIR}/examples/consumer -B ${consumer} -G Ninja -DCMAKE_MAKE_PROGRAM=${MAKE_PROGRAM}
    -DCMAKE_CXX_COMPILER=${CXX} -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH=${prefix}
    -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF)
file(STRINGS ${consumer}/CMakeCache.txt found REGEX "^iblkit_DIR:")
if(NOT found STREQUAL "iblkit_DIR:PATH=${prefix}/lib/cmake/iblkit")
  message(FATAL_ERROR "the consumer found another iblkit: ${found}")
endif()
run(${MAKE_PROGRAM} -C ${consumer})
expect_files(${consumer}/shaders GgxPeak.spv GgxPeak.json GgxPeak.glsl GgxPeak.msl GgxPeak.run.json)
run(${consumer}/consumer ${consumer}/shaders/GgxPeak.run.json)
expect_in("${output}" "1 of 1 expectations passed")
expect_in("${output}" "specular mips from 32²")
# The run file's shader is the SPIR-V the build wrote, not the HLSL.
expect_in("${output}" "GgxPeak.spv")

# pkg-config: a program compiled and linked with its flags alone, run against the installed library.
set(ENV{PKG_CONFIG_PATH} ${prefix}/lib/pkgconfig)
run(pkg-config --cflags --libs iblkit)
string(STRIP "${output}" flags)
separate_arguments(flags UNIX_COMMAND "${flags}")
file(WRITE ${WORK_DIR}/version.cpp
  "#include <iblkit/iblkit.hpp>\n#include <iostream>\nint main() { std::cout << iblkit::version() << '\\n'; }\n")
run(${CXX} ${WORK_DIR}/version.cpp ${flags} -Wl,-rpath,${prefix}/lib -o ${WORK_DIR}/version)
run(${WORK_DIR}/version)
expect_in("${output}" "${VERSION}")
file(REMOVE_RECURSE ${WORK_DIR})
