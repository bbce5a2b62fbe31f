# Generates the glad2 GL 4.5 core loader at build time with Debian's python3-glad (offline:
# --reproducible keeps it from fetching specs over the network).
find_program(RRC_GLAD_EXECUTABLE glad PATHS /usr/bin NO_DEFAULT_PATH)
find_program(RRC_GLAD_EXECUTABLE glad)
if(NOT RRC_GLAD_EXECUTABLE)
  message(FATAL_ERROR "glad (Debian package python3-glad) not found: run scripts/setup")
endif()

set(RRC_GLAD_DIR ${PROJECT_BINARY_DIR}/glad)
add_custom_command(
  OUTPUT ${RRC_GLAD_DIR}/src/gl.c ${RRC_GLAD_DIR}/include/glad/gl.h ${RRC_GLAD_DIR}/include/KHR/khrplatform.h
  COMMAND ${RRC_GLAD_EXECUTABLE} --quiet --reproducible --api gl:core=4.5
          --extensions GL_KHR_debug,GL_ARB_clip_control --out-path ${RRC_GLAD_DIR} c
  COMMENT "Generating the glad2 GL 4.5 core loader"
  VERBATIM)
add_custom_target(rrc_glad_generate DEPENDS ${RRC_GLAD_DIR}/src/gl.c)
