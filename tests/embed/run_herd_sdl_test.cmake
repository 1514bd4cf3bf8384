# Run by CTest: builds the consumer project in EMBED_SOURCE_DIR against the scratch install
# PREFIX (install.cmake; consumer.cmake for the other variables) and runs its herd_sdl, the
# SDL_Renderer example of ossa::draw, for one frame offscreen (a software renderer on an
# SDL_Surface): it writes WORK_DIR/herd_<look>.bmp and fails unless every creature is drawn.
include(${CMAKE_CURRENT_LIST_DIR}/consumer.cmake)

build_consumer(${EMBED_SOURCE_DIR} ${WORK_DIR}/build)
if(NOT EXISTS ${WORK_DIR}/build/herd_sdl)
  message(FATAL_ERROR "herd_sdl was not built (ossa::draw or SDL2 >= 2.0.18 not found by the consumer)")
endif()
foreach(look body xray bones)
  run(${WORK_DIR}/build/herd_sdl --look ${look} --frame ${WORK_DIR}/herd_${look}.bmp)
  if(NOT run_out MATCHES "herd_sdl: 6 creatures, [1-9][0-9]* triangles")
    message(FATAL_ERROR "herd_sdl (${look}) did not draw six creatures:\n${run_out}")
  endif()
  file(SIZE ${WORK_DIR}/herd_${look}.bmp size)
  if(size LESS 1000000)
    message(FATAL_ERROR "herd_sdl (${look}) wrote ${size} bytes, not a 1280x480 frame")
  endif()
endforeach()

# No OpenGL in the example's own code: no GL header, no gl* call, no GL context asked of SDL.
file(READ ${EMBED_SOURCE_DIR}/herd_sdl.cpp herd_source)
if(herd_source MATCHES "(#include <(GL|epoxy)|[^a-zA-Z_]gl[A-Z][A-Za-z]*\\(|SDL_GL_|SDL_WINDOW_OPENGL)")
  message(FATAL_ERROR "tests/embed/herd_sdl.cpp uses OpenGL (${CMAKE_MATCH_1}): it must draw through SDL_Renderer alone")
endif()
