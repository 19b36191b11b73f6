# `cpack -G DEB` makes a package whose dependencies are Debian 12's packages, and whose files,
# unpacked into a scratch root (dpkg -x), bake the built-in sky with nothing of the source tree.
# Run with -DBUILD_DIR=<the kit's build> -DWORK_DIR=<scratch folder>.
include(${CMAKE_CURRENT_LIST_DIR}/../support/run_step.cmake)
file(REMOVE_RECURSE ${WORK_DIR})
run(cpack -G DEB -B ${WORK_DIR}/package --config ${BUILD_DIR}/CPackConfig.cmake)
file(GLOB deb ${WORK_DIR}/package/iblkit_*.deb)
list(LENGTH deb count)
if(NOT count EQUAL 1)
  message(FATAL_ERROR "expected one iblkit_*.deb in ${WORK_DIR}/package, found: ${deb}")
endif()
run(dpkg-deb --field ${deb} Depends)
# dpkg-shlibdeps's (the C++ runtime, OpenEXR, at least), and what the program opens at run time:
# the Vulkan loader and lavapipe, the default device.
foreach(package libstdc++6 libopenexr libvulkan1 mesa-vulkan-drivers)
  expect_in("${output}" "${package}")
endforeach()

set(root ${WORK_DIR}/root)
run(dpkg -x ${deb} ${root})
expect_files(${root}/usr bin/iblkit include/iblkit/iblkit.hpp lib/cmake/iblkit/iblkitConfig.cmake lib/pkgconfig/iblkit.pc
             share/iblkit/hlsl/document/Common/PBR.fxh)
execute_process(COMMAND ${root}/usr/bin/iblkit bake -o ${WORK_DIR}/bake --size 32 --lut-size 64 --irradiance-size 8
                        --no-cache --quiet --json
                WORKING_DIRECTORY ${WORK_DIR} RESULT_VARIABLE result OUTPUT_VARIABLE summary ERROR_VARIABLE err)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "the packaged iblkit bake failed (${result}): ${err}")
endif()
# The packaged program's built-in kernels (libexec/iblkit/kernels) serve it: it compiles none.
string(JSON compiled GET "${summary}" compiled_kernels compiled)
string(JSON built_in GET "${summary}" compiled_kernels built_in)
if(NOT compiled EQUAL 0 OR built_in LESS 9)
  message(FATAL_ERROR "the packaged iblkit compiled ${compiled} kernels and took ${built_in} from its own")
endif()
expect_files(${WORK_DIR}/bake specular.ktx2 brdf_lut.ktx2 irradiance.ktx2 manifest.json preview.png)
file(REMOVE_RECURSE ${WORK_DIR})
