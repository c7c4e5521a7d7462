#include "agaa/temporal/reprojection.h"

namespace agaa {

double radicalInverse(uint32_t index, uint32_t base) {
    double result = 0.0, digit = 1.0 / base;
    for (; index > 0; index /= base, digit /= base)
        result += double(index % base) * digit;
    return result;
}

glm::vec2 haltonJitter(uint64_t frame, uint32_t phases) {
    const uint32_t index = 1 + uint32_t(frame % (phases ? phases : 1));
    return {float(radicalInverse(index, 2) - 0.5), float(radicalInverse(index, 3) - 0.5)};
}

glm::mat4 reprojectionMatrix(const shared::FrameConstants& previous, const shared::FrameConstants& current) {
    const glm::dmat4 m =
        glm::dmat4(previous.proj) * glm::dmat4(previous.view) * glm::inverse(glm::dmat4(current.view));
    return glm::mat4(m);
}

} // namespace agaa
