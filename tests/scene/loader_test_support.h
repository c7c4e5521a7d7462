#pragma once
// Shared by the loader's refusal tests: the SceneError a file must raise, and a fixture with a
// fresh temporary folder per test.

#include "engine/scene/gltf_loader.h"

#include "gltf_test_model.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace eng::scene::test {

// Loads path and returns the SceneError message; fails the test if it loads.
inline std::string loadError(const std::filesystem::path& path) {
    try {
        loadGltf(path);
    } catch (const SceneError& e) {
        return e.what();
    }
    ADD_FAILURE() << path << " loaded but must have been refused";
    return {};
}

class TempDirTest : public ::testing::Test {
  protected:
    void SetUp() override {
        m_dir = makeTempDir(::testing::UnitTest::GetInstance()->current_test_info()->name());
    }
    void TearDown() override { std::filesystem::remove_all(m_dir); }
    std::filesystem::path m_dir;
};

} // namespace eng::scene::test
