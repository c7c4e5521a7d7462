# Fails when a C++ file outside engine/graph names an image layout (VK_IMAGE_LAYOUT_*): the
# render graph decides every layout (engine/graph/use.cpp) and hands it out through
# Context::layout(), the render passes it begins and the Use table, so a layout spelled anywhere
# else can drift from the one the barriers produced. samples/ too: the viewer's ImGui render pass
# takes its layouts from the Use table (engine/graph/legacy_render_pass).
# Usage: cmake -DROOT=<dir> -P no_image_layouts.cmake
if(NOT ROOT)
  message(FATAL_ERROR "no_image_layouts.cmake: pass -DROOT=<source root>")
endif()
file(GLOB_RECURSE sources LIST_DIRECTORIES false
     ${ROOT}/engine/*.cpp ${ROOT}/engine/*.h ${ROOT}/agaa/*.cpp ${ROOT}/agaa/*.h
     ${ROOT}/tools/*.cpp ${ROOT}/tools/*.h ${ROOT}/samples/*.cpp ${ROOT}/samples/*.h ${ROOT}/agaa/*.cpp.txt)
include(${CMAKE_CURRENT_LIST_DIR}/lint_lines.cmake)
set(found "")
foreach(source IN LISTS sources)
  file(RELATIVE_PATH relative ${ROOT} ${source})
  if(NOT relative MATCHES "^engine/graph/")
    lint_lines(found ${ROOT} ${source} "VK_IMAGE_LAYOUT_")
  endif()
endforeach()
if(found)
  message(FATAL_ERROR "image layouts named outside engine/graph (declare the use, attach it with "
                      "Builder::color/depthStencil, or ask Context::layout()):${found}")
endif()
message(STATUS "no image layout outside engine/graph under ${ROOT}")
