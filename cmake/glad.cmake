# glad 2 (Debian's python3-glad) generates the GL 4.5 core and EGL loaders into the build tree.
# --reproducible uses the specifications bundled with the package: no network.
find_program(GLAD_EXECUTABLE glad REQUIRED)
set(GLAD_OUT "${CMAKE_CURRENT_BINARY_DIR}/glad")
set(GLAD_GL_EXTENSIONS GL_KHR_debug,GL_ARB_indirect_parameters,GL_ARB_shader_draw_parameters)
set(GLAD_EGL_EXTENSIONS
    EGL_EXT_platform_base,EGL_EXT_platform_device,EGL_EXT_device_base,EGL_EXT_device_enumeration,EGL_EXT_device_query,EGL_MESA_platform_surfaceless,EGL_KHR_no_config_context,EGL_KHR_create_context)
add_custom_command(
    OUTPUT "${GLAD_OUT}/gl/src/gl.c" "${GLAD_OUT}/gl/include/glad/gl.h"
    COMMAND "${GLAD_EXECUTABLE}" --quiet --reproducible --api gl:core=4.5
            --extensions ${GLAD_GL_EXTENSIONS} --out-path "${GLAD_OUT}/gl" c --loader
    COMMENT "Generating glad GL 4.5 core loader"
    VERBATIM)
add_custom_command(
    OUTPUT "${GLAD_OUT}/egl/src/egl.c" "${GLAD_OUT}/egl/include/glad/egl.h"
    COMMAND "${GLAD_EXECUTABLE}" --quiet --reproducible --api egl=1.5
            --extensions ${GLAD_EGL_EXTENSIONS} --out-path "${GLAD_OUT}/egl" c --loader
    COMMENT "Generating glad EGL loader"
    VERBATIM)
add_library(glad_gl STATIC "${GLAD_OUT}/gl/src/gl.c")
target_include_directories(glad_gl SYSTEM PUBLIC "${GLAD_OUT}/gl/include")
target_link_libraries(glad_gl PUBLIC ${CMAKE_DL_LIBS})
set_target_properties(glad_gl PROPERTIES POSITION_INDEPENDENT_CODE ON)
add_library(glad_egl STATIC "${GLAD_OUT}/egl/src/egl.c")
target_include_directories(glad_egl SYSTEM PUBLIC "${GLAD_OUT}/egl/include")
target_link_libraries(glad_egl PUBLIC ${CMAKE_DL_LIBS})
set_target_properties(glad_egl PROPERTIES POSITION_INDEPENDENT_CODE ON)
