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

# The members of the object shaders[index].key of a manifest as a list of NAME=VALUE.
function(_iblkit_manifest_assignments text index key out)
  set(assignments "")
  string(JSON count ERROR_VARIABLE missing LENGTH ${text} shaders ${index} ${key})
  if(NOT missing AND count GREATER 0)
    math(EXPR last "${count} - 1")
    foreach(member_index RANGE ${last})
      string(JSON member MEMBER ${text} shaders ${index} ${key} ${member_index})
      string(JSON value GET ${text} shaders ${index} ${key} ${member})
      list(APPEND assignments ${member}=${value})
    endforeach()
  endif()
  set(${out} ${assignments} PARENT_SCOPE)
endfunction()

# Adds every shader of a manifest (hlsl/shaders.json) with iblkit_add_shader, the `shaders`
# target that builds them all, and `refresh-glsl`, which rewrites the committed forms in glsl/.
function(iblkit_add_shaders_from_manifest manifest)
  file(READ ${manifest} text)
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${manifest})
  get_filename_component(folder ${manifest} DIRECTORY)
  string(JSON count LENGTH ${text} shaders)
  math(EXPR last "${count} - 1")
  foreach(index RANGE ${last})
    string(JSON name GET ${text} shaders ${index} name)
    string(JSON source GET ${text} shaders ${index} source)
    string(JSON entry ERROR_VARIABLE no_entry GET ${text} shaders ${index} entry)
    if(no_entry)
      set(entry main)
    endif()
    string(JSON stage ERROR_VARIABLE no_stage GET ${text} shaders ${index} stage)
    if(no_stage)
      set(stage "")
    endif()
    set(includes ${folder})
    string(JSON include_count ERROR_VARIABLE no_includes LENGTH ${text} shaders ${index} include)
    if(NOT no_includes AND include_count GREATER 0)
      math(EXPR last_include "${include_count} - 1")
      foreach(include_index RANGE ${last_include})
        string(JSON include GET ${text} shaders ${index} include ${include_index})
        list(APPEND includes ${folder}/${include})
      endforeach()
    endif()
    _iblkit_manifest_assignments("${text}" ${index} image_formats formats)
    _iblkit_manifest_assignments("${text}" ${index} defines defines)
    iblkit_add_shader(${name} SOURCE ${folder}/${source} ENTRY ${entry} STAGE "${stage}" INCLUDE_DIRS ${includes}
                      DEFINES ${defines} IMAGE_FORMATS ${formats})
  endforeach()
  get_property(outputs GLOBAL PROPERTY IBLKIT_SHADER_OUTPUTS)
  add_custom_target(shaders ALL DEPENDS ${outputs})
  file(RELATIVE_PATH relative_manifest ${CMAKE_SOURCE_DIR} ${manifest})
  add_custom_target(refresh-glsl
    COMMAND $<TARGET_FILE:iblkit> compile-all ${relative_manifest} -o glsl --only glsl,essl,msl,reflect
    WORKING_DIRECTORY ${CMAKE_SOURCE_DIR}
    DEPENDS iblkit
    COMMENT "Rewriting the committed GLSL, ESSL and MSL forms in glsl/"
    VERBATIM)
endfunction()
