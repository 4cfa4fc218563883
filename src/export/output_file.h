// A file opened for writing whose every failure throws with the system's reason, for the mesh writers to use
// inside draw::writeAtomically (which removes the partial file and names the destination).
#pragma once

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>

namespace simeco::exporter {

class OutputFile {
public:
    explicit OutputFile(const std::filesystem::path& path) : file_(std::fopen(path.c_str(), "wb")) {
        if (file_ == nullptr) {
            throw std::runtime_error(std::strerror(errno));
        }
    }
    OutputFile(const OutputFile&) = delete;
    OutputFile& operator=(const OutputFile&) = delete;
    ~OutputFile() {
        if (file_ != nullptr) {
            std::fclose(file_);
        }
    }

    void write(const void* data, std::size_t bytes) {
        if (bytes != 0 && std::fwrite(data, 1, bytes, file_) != bytes) {
            throw std::runtime_error(std::strerror(errno));
        }
    }
    void write(std::string_view text) { write(text.data(), text.size()); }

    // Flushes and closes; a full disk often shows only here.
    void close() {
        std::FILE* file = file_;
        file_ = nullptr;
        if (std::fclose(file) != 0) {
            throw std::runtime_error(std::strerror(errno));
        }
    }

private:
    std::FILE* file_;
};

} // namespace simeco::exporter
