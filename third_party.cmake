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

if(AGAA_BUILD_VIEWER)
  find_package(glfw3 CONFIG QUIET)
  agaa_require(glfw3_FOUND "GLFW (sample viewer only)" "libglfw3-dev")
endif()

# Chart.js for the self-contained report (inlined, never fetched).
if(AGAA_BUILD_TOOLS)
  find_file(AGAA_CHARTJS chart.min.js PATHS /usr/share/javascript/chart.js NO_DEFAULT_PATH)
endif()
