# Build-time shader compilation with the kit's own compiler, the program iblkit::cli.
#
# iblkit_add_shader(NAME SOURCE src.hlsl [ENTRY main] [STAGE comp] [TARGET tgt] [OUTPUT_DIR dir]
#                   [INCLUDE_DIRS dir...] [DEFINES NAME=VALUE...] [IMAGE_FORMATS Resource=format...]
#                   [FORMS glsl essl msl hlsl vulkan-glsl vulkan-essl])
# compiles SOURCE to OUTPUT_DIR/NAME.spv (default ${CMAKE_BINARY_DIR}/shaders) with its reflection
# NAME.json and each form of FORMS as NAME.<form>, rebuilt whenever the source or anything it
# #includes changes (through the depfile). With TARGET, tgt is built after the shader.
# find_package(iblkit) sets iblkit_HLSL_DIR, for INCLUDE_DIRS: the kit's Common/PBR.fxh and the rest.
if(NOT TARGET iblkit::cli)
  message(FATAL_ERROR "IblkitShaders.cmake needs the target iblkit::cli: find_package(iblkit) defines it")
endif()

function(iblkit_add_shader name)
  cmake_parse_arguments(PARSE_ARGV 1 ARG "" "SOURCE;ENTRY;STAGE;TARGET;OUTPUT_DIR"
                        "INCLUDE_DIRS;DEFINES;IMAGE_FORMATS;FORMS")
  if(NOT ARG_SOURCE)
    message(FATAL_ERROR "iblkit_add_shader(${name}): SOURCE is required")
  endif()
  if(NOT ARG_ENTRY)
    set(ARG_ENTRY main)
  endif()
  set(out_dir ${ARG_OUTPUT_DIR})
  if(NOT out_dir)
    set(out_dir ${CMAKE_BINARY_DIR}/shaders)
  endif()
  set(spv ${out_dir}/${name}.spv)
  set(outputs ${spv} ${out_dir}/${name}.json)
  set(flags -E ${ARG_ENTRY})
  if(ARG_STAGE)
    list(APPEND flags -S ${ARG_STAGE})
  endif()
  foreach(dir IN LISTS ARG_INCLUDE_DIRS)
    list(APPEND flags -I ${dir})
  endforeach()
  foreach(define IN LISTS ARG_DEFINES)
    list(APPEND flags -D ${define})
  endforeach()
  foreach(format IN LISTS ARG_IMAGE_FORMATS)
    list(APPEND flags --image-format ${format})
  endforeach()
  foreach(form IN LISTS ARG_FORMS)
    if(NOT form MATCHES "^(glsl|essl|msl|hlsl|vulkan-glsl|vulkan-essl)$")
      message(FATAL_ERROR "iblkit_add_shader(${name}): unknown form '${form}' "
                          "(glsl, essl, msl, hlsl, vulkan-glsl, vulkan-essl)")
    endif()
    list(APPEND flags --${form} ${out_dir}/${name}.${form})
    list(APPEND outputs ${out_dir}/${name}.${form})
  endforeach()
  add_custom_command(
    OUTPUT ${outputs}
    COMMAND ${CMAKE_COMMAND} -E make_directory ${out_dir}
    COMMAND $<TARGET_FILE:iblkit::cli> compile ${ARG_SOURCE} -o ${spv} --reflect ${out_dir}/${name}.json ${flags}
            -MD -MF ${spv}.d
    DEPENDS iblkit::cli ${ARG_SOURCE}
    DEPFILE ${spv}.d
    COMMENT "iblkit compile ${name}"
    VERBATIM)
  if(ARG_TARGET)
    add_custom_target(${ARG_TARGET}_shader_${name} DEPENDS ${outputs})
    add_dependencies(${ARG_TARGET} ${ARG_TARGET}_shader_${name})
  endif()
endfunction()
