#include "agaa/common/technique.h"

#include <stdexcept>

namespace agaa {

GeometryDrawer& frameDrawer(const FrameInputs& in, GeometryDrawer* sceneDrawer, const std::string& pass) {
    if (in.geometry) return *in.geometry;
    if (sceneDrawer) return *sceneDrawer;
    throw std::invalid_argument(
        pass + ": FrameInputs::geometry is null and the technique was created without a "
               "GpuScene to draw (TechniqueContent::scene): give the frame a GeometryDrawer");
}

EnvironmentBindings frameEnvironment(const FrameInputs& in, const eng::frame::GpuScene* scene,
                                     const std::string& technique) {
    if (in.environment) return *in.environment;
    if (scene) return environmentBindings(*scene);
    throw std::invalid_argument(technique +
                                ": FrameInputs::environment is null and the technique was created "
                                "without a GpuScene (TechniqueContent::scene): give the frame its "
                                "EnvironmentBindings");
}

} // namespace agaa
