# Every external dependency, found in one place. A missing one stops the
# configure step with the Debian package that provides it (tools/deps.sh
# installs them all).

function(agaa_require found what package)
  if(NOT ${found})
    message(FATAL_ERROR "AGAA: ${what} not found. Install the Debian package '${package}' "
                        "(or run tools/deps.sh, which installs every dependency).")
  endif()
endfunction()

find_package(Vulkan QUIET)
agaa_require(Vulkan_FOUND "Vulkan loader and headers" "libvulkan-dev")

find_program(GLSLANG_VALIDATOR glslangValidator)
agaa_require(GLSLANG_VALIDATOR "glslangValidator (GLSL to SPIR-V compiler)" "glslang-tools")

find_package(glm CONFIG QUIET)
agaa_require(glm_FOUND "GLM" "libglm-dev")

find_package(TinyGLTF CONFIG QUIET)
agaa_require(TinyGLTF_FOUND "tinygltf" "libtinygltf-dev")

find_package(nlohmann_json CONFIG QUIET)
agaa_require(nlohmann_json_FOUND "nlohmann-json (used by tinygltf and the stats writer)" "nlohmann-json3-dev")

find_path(STB_INCLUDE_DIR stb_image_write.h PATH_SUFFIXES stb)
agaa_require(STB_INCLUDE_DIR "stb (stb_image, stb_image_write)" "libstb-dev")
find_library(STB_LIBRARY stb)
agaa_require(STB_LIBRARY "stb library" "libstb-dev")
add_library(agaa_stb INTERFACE)
target_include_directories(agaa_stb SYSTEM INTERFACE ${STB_INCLUDE_DIR})
target_link_libraries(agaa_stb INTERFACE ${STB_LIBRARY})
# Installed with the package: agaa::io and agaa::scene link it privately, which a static library
# still passes on to the host's link.
set_target_properties(agaa_stb PROPERTIES EXPORT_NAME stb)

find_package(OpenEXR CONFIG QUIET)
agaa_require(OpenEXR_FOUND "OpenEXR" "libopenexr-dev")

if(AGAA_BUILD_TESTS)
  find_package(GTest QUIET)
  agaa_require(GTest_FOUND "GoogleTest" "libgtest-dev")
  include(GoogleTest)
endif()

# The sample viewer: GLFW and Dear ImGui 1.86 (Debian libimgui-dev: a static libimgui.a, and the
# GLFW and Vulkan backends as sources under the package's examples, compiled by the viewer).
set(AGAA_VIEWER_ENABLED OFF)
if(NOT AGAA_BUILD_VIEWER MATCHES "^(AUTO|ON|OFF)$")
  message(FATAL_ERROR "AGAA_BUILD_VIEWER=${AGAA_BUILD_VIEWER}: allowed values are AUTO, ON, OFF")
endif()
if(NOT AGAA_BUILD_VIEWER STREQUAL "OFF" AND AGAA_BUILD_TOOLS AND AGAA_BUILD_SAMPLES)
  find_package(glfw3 CONFIG QUIET)
  find_path(IMGUI_INCLUDE_DIR imgui.h PATH_SUFFIXES imgui)
  find_library(IMGUI_LIBRARY imgui)
  find_path(IMGUI_BACKEND_DIR imgui_impl_vulkan.cpp
            PATHS /usr/share/doc/libimgui-dev/examples/backends NO_DEFAULT_PATH)
  if(glfw3_FOUND AND IMGUI_INCLUDE_DIR AND IMGUI_LIBRARY AND IMGUI_BACKEND_DIR)
    set(AGAA_VIEWER_ENABLED ON)
  elseif(AGAA_BUILD_VIEWER STREQUAL "ON")
    agaa_require(glfw3_FOUND "GLFW (sample viewer)" "libglfw3-dev")
    agaa_require(IMGUI_LIBRARY "Dear ImGui with its GLFW and Vulkan backends (sample viewer)" "libimgui-dev")
    agaa_require(IMGUI_BACKEND_DIR "Dear ImGui backend sources (sample viewer)" "libimgui-dev")
  else()
    message(STATUS "AGAA: sample viewer not built (needs libglfw3-dev and libimgui-dev: tools/deps.sh)")
  endif()
endif()

# Chart.js for the self-contained report (inlined, never fetched).
if(AGAA_BUILD_TOOLS)
  find_file(AGAA_CHARTJS chart.min.js PATHS /usr/share/javascript/chart.js NO_DEFAULT_PATH)
endif()
