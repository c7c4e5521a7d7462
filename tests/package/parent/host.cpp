// Only configured (and one shader compiled) by tests/package/subdirectory_test.cmake: the point is
// that a host target links agaa::agaa beside its own eng_vk.
#include <agaa/agaa.h>

int main() {
    return agaa::isKnownMethod("agaa") ? 0 : 1;
}
