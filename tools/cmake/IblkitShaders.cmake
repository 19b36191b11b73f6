# Build-time shader compilation with the kit's own compiler.
#
# iblkit_add_shader(NAME SOURCE src.hlsl [ENTRY main] [STAGE comp] [INCLUDE_DIRS dir...]
#                   [DEFINES NAME=VALUE...] [IMAGE_FORMATS Resource=format...])
# compiles SOURCE to ${CMAKE_BINARY_DIR}/shaders/NAME.spv with its reflection NAME.json,
# rebuilt whenever the source or anything it #includes changes (through the depfile).
function(iblkit_add_shader name)
  cmake_parse_arguments(PARSE_ARGV 1 ARG "" "SOURCE;ENTRY;STAGE" "INCLUDE_DIRS;DEFINES;IMAGE_FORMATS")
  if(NOT ARG_ENTRY)
    set(ARG_ENTRY main)
  endif()
  set(out_dir ${CMAKE_BINARY_DIR}/shaders)
  set(spv ${out_dir}/${name}.spv)
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
  add_custom_command(
    OUTPUT ${spv} ${out_dir}/${name}.json
    COMMAND ${CMAKE_COMMAND} -E make_directory ${out_dir}
    COMMAND $<TARGET_FILE:iblkit> compile ${ARG_SOURCE} -o ${spv} --reflect ${out_dir}/${name}.json ${flags}
            -MD -MF ${spv}.d
    DEPENDS iblkit ${ARG_SOURCE}
    DEPFILE ${spv}.d
    COMMENT "iblkit compile ${name}"
    VERBATIM)
  set_property(GLOBAL APPEND PROPERTY IBLKIT_SHADER_OUTPUTS ${spv})
endfunction()

# `refresh-glsl`: rewrites the committed GLSL, ESSL and MSL forms of every shader of a manifest
# (hlsl/shaders.json) in glsl/.
function(iblkit_add_refresh_glsl manifest)
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${manifest})
  file(RELATIVE_PATH relative_manifest ${CMAKE_SOURCE_DIR} ${manifest})
  add_custom_target(refresh-glsl
    COMMAND $<TARGET_FILE:iblkit> compile-all ${relative_manifest} -o glsl --only glsl,essl,msl,reflect
    WORKING_DIRECTORY ${CMAKE_SOURCE_DIR}
    DEPENDS iblkit
    COMMENT "Rewriting the committed GLSL, ESSL and MSL forms in glsl/"
    VERBATIM)
endfunction()
