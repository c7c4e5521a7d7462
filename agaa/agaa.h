#pragma once
// The whole module for a host: every technique (one Technique per method, created by name through
// createTechnique or constructed directly), the render graph they add passes to, the device
// layer, the scene and its GPU upload, the per-frame helpers and the image files.
//
// In-tree (add_subdirectory) and installed (find_package(agaa CONFIG), target agaa::agaa) a host
// writes #include <agaa/agaa.h>; installed, the headers live under <prefix>/include/agaa/ and
// that folder is the one include directory agaa::agaa adds.

#include "agaa/aggregate/aggregate.h"
#include "agaa/common/frame_inputs.h"
#include "agaa/common/frame_recorder.h"
#include "agaa/common/host_targets.h"
#include "agaa/common/technique.h"
#include "agaa/fxaa/fxaa.h"
#include "agaa/methods.h"
#include "agaa/reference/reference.h"
#include "agaa/sbaa/sbaa.h"
#include "agaa/simple_complex/simple_complex.h"
#include "agaa/streaming/streaming.h"
#include "engine/frame/frame_constants.h"
#include "engine/frame/frame_runner.h"
#include "engine/frame/gpu_scene.h"
#include "engine/frame/readback.h"
#include "engine/frame/sample_pattern.h"
#include "engine/frame/uniform_ring.h"
#include "engine/graph/graph.h"
#include "engine/io/image.h"
#include "engine/scene/gltf_loader.h"
#include "engine/scene/scene.h"
#include "engine/scene/scene_error.h"
#include "engine/scene/scenegen.h"
#include "engine/vk/check.h"
#include "engine/vk/device.h"
#include "engine/vk/device_setup.h"
#include "engine/vk/resources.h"
