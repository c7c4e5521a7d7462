#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>

namespace eng::io {

// The one error type of engine/io. File errors carry the file so that a tool can report it
// without parsing the message; the message always names the file too.
class IoError : public std::runtime_error {
  public:
    explicit IoError(const std::string& message) : std::runtime_error(message) {}

    IoError(const std::filesystem::path& file, const std::string& message)
        : std::runtime_error("'" + file.string() + "': " + message), m_file(file) {}

    // Empty when the error is not about a file (for example a metric given images of different sizes).
    const std::filesystem::path& file() const noexcept { return m_file; }

  private:
    std::filesystem::path m_file;
};

} // namespace eng::io
