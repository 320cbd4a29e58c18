# The interactive viewer's dependencies (Debian: libglfw3-dev libimgui-dev libstb-dev; ../shared/ENVIRONMENT.md):
# GLFW's CMake config, OpenGL through GLVND, and Dear ImGui and stb through pkg-config (Debian's static libimgui.a
# already holds the GLFW and OpenGL 3 backends). HOOKE_BUILD_VIEWER: AUTO builds the viewer when all are present,
# ON requires them, OFF skips it. Sets HOOKE_VIEWER_ENABLED.
set(HOOKE_VIEWER_ENABLED OFF)
if(NOT HOOKE_BUILD_VIEWER STREQUAL "OFF")
  set(OpenGL_GL_PREFERENCE GLVND)
  find_package(OpenGL QUIET)
  find_package(Threads REQUIRED)
  find_package(glfw3 3.3 CONFIG QUIET)
  find_package(PkgConfig QUIET)
  if(PkgConfig_FOUND)
    pkg_check_modules(IMGUI QUIET IMPORTED_TARGET imgui)
  endif()
  if(OpenGL_OpenGL_FOUND AND glfw3_FOUND AND IMGUI_FOUND)
    set(HOOKE_VIEWER_ENABLED ON)
  elseif(HOOKE_BUILD_VIEWER STREQUAL "ON")
    message(FATAL_ERROR "HOOKE_BUILD_VIEWER=ON needs GLFW 3.3, OpenGL and Dear ImGui: run scripts/setup.sh")
  else()
    message(STATUS "hooke: the viewer is not built (GLFW, OpenGL or Dear ImGui missing; scripts/setup.sh installs them)")
  endif()
endif()
