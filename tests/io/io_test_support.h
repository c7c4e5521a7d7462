#pragma once

#include "engine/io/io_error.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <unistd.h>

namespace eng::io::test {

// A fresh directory per test (named after the test and the process) so that CTest can run the
// discovered tests in parallel; removed afterwards.
class ScratchDir {
  public:
    ScratchDir() {
        const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
        m_path =
            std::filesystem::temp_directory_path() / ("eng_io_" + std::string(info->test_suite_name()) + "_" +
                                                      info->name() + "_" + std::to_string(::getpid()));
        std::filesystem::remove_all(m_path);
        std::filesystem::create_directories(m_path);
    }
    ~ScratchDir() {
        std::error_code ec;
        std::filesystem::remove_all(m_path, ec);
    }
    ScratchDir(const ScratchDir&) = delete;
    ScratchDir& operator=(const ScratchDir&) = delete;

    std::filesystem::path operator/(const std::string& name) const { return m_path / name; }
    const std::filesystem::path& path() const { return m_path; }

  private:
    std::filesystem::path m_path;
};

// Expects `call` to throw IoError whose message and file() both name `file`.
template <typename Call> void expectIoErrorNaming(const std::filesystem::path& file, Call&& call) {
    try {
        call();
        ADD_FAILURE() << "expected IoError for " << file;
    } catch (const IoError& e) {
        EXPECT_NE(std::string(e.what()).find(file.string()), std::string::npos)
            << "the message must name the file; got: " << e.what();
        EXPECT_EQ(e.file(), file) << "IoError::file() must carry the file";
    }
}

} // namespace eng::io::test
