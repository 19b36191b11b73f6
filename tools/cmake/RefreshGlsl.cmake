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
