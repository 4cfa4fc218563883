#include "draw/image_writers.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <png.h>

#include <Imath/half.h>
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfOutputFile.h>

namespace simeco::draw {
namespace {

void checkFrame(const std::filesystem::path& path, const Frame& frame) {
    std::size_t pixels = frame.pixelCount();
    if (pixels == 0) {
        throw OutputError("cannot write '" + path.string() + "': the frame is empty");
    }
    if (frame.rgba.size() != 4 * pixels || frame.depth.size() != pixels || frame.plant.size() != pixels ||
        frame.organ.size() != pixels) {
        throw OutputError("cannot write '" + path.string() + "': the frame's buffers do not match its " +
                          std::to_string(frame.width) + " x " + std::to_string(frame.height) + " size");
    }
}

} // namespace

std::uint8_t previewByte(float linear) {
    float x = std::isfinite(linear) ? std::max(linear, 0.0f) : 0.0f;
    float mapped = std::clamp((x * (2.51f * x + 0.03f)) / (x * (2.43f * x + 0.59f) + 0.14f), 0.0f, 1.0f);
    float encoded = mapped <= 0.0031308f ? 12.92f * mapped : 1.055f * std::pow(mapped, 1.0f / 2.4f) - 0.055f;
    return static_cast<std::uint8_t>(std::lround(encoded * 255.0f));
}

void writePng(const std::filesystem::path& path, const Frame& frame) {
    OutputBatch batch;
    writePng(batch, path, frame);
    batch.commit();
}

void writeExr(const std::filesystem::path& path, const Frame& frame) {
    OutputBatch batch;
    writeExr(batch, path, frame);
    batch.commit();
}

void writePng(OutputBatch& batch, const std::filesystem::path& path, const Frame& frame) {
    checkFrame(path, frame);
    std::vector<std::uint8_t> bytes(4 * frame.pixelCount());
    for (std::size_t i = 0; i < frame.pixelCount(); ++i) {
        for (std::size_t c = 0; c < 3; ++c) {
            bytes[4 * i + c] = previewByte(frame.rgba[4 * i + c]);
        }
        bytes[4 * i + 3] = 255;
    }
    batch.write(path, [&](const std::filesystem::path& temporary) {
        png_image image{};
        image.version = PNG_IMAGE_VERSION;
        image.width = frame.width;
        image.height = frame.height;
        image.format = PNG_FORMAT_RGBA;
        int written = png_image_write_to_file(&image, temporary.c_str(), 0, bytes.data(), 0, nullptr);
        std::string message = image.message;
        png_image_free(&image);
        if (written == 0) {
            throw std::runtime_error(message.empty() ? "libpng failed" : message);
        }
    });
}

void writeExr(OutputBatch& batch, const std::filesystem::path& path, const Frame& frame) {
    checkFrame(path, frame);
    std::vector<Imath::half> rgba(frame.rgba.size());
    std::transform(frame.rgba.begin(), frame.rgba.end(), rgba.begin(), [](float v) { return Imath::half(v); });

    batch.write(path, [&](const std::filesystem::path& temporary) {
        int width = static_cast<int>(frame.width);
        int height = static_cast<int>(frame.height);
        Imf::Header header(width, height);
        header.compression() = Imf::ZIP_COMPRESSION;
        for (const char* name : {"R", "G", "B", "A"}) {
            header.channels().insert(name, Imf::Channel(Imf::HALF));
        }
        header.channels().insert("Z", Imf::Channel(Imf::FLOAT));
        header.channels().insert("plant", Imf::Channel(Imf::UINT));
        header.channels().insert("organ", Imf::Channel(Imf::UINT));

        Imf::FrameBuffer buffer;
        const std::size_t pixel = 4 * sizeof(Imath::half);
        const char* names[] = {"R", "G", "B", "A"};
        for (std::size_t c = 0; c < 4; ++c) {
            buffer.insert(names[c],
                          Imf::Slice(Imf::HALF, reinterpret_cast<char*>(rgba.data() + c), pixel, pixel * frame.width));
        }
        // OpenEXR's slices take writable pointers but only read from them when writing.
        auto bytes = [](const auto& v) {
            return reinterpret_cast<char*>(const_cast<void*>(static_cast<const void*>(v.data())));
        };
        buffer.insert("Z", Imf::Slice(Imf::FLOAT, bytes(frame.depth), sizeof(float), sizeof(float) * frame.width));
        buffer.insert("plant", Imf::Slice(Imf::UINT, bytes(frame.plant), sizeof(std::uint32_t),
                                          sizeof(std::uint32_t) * frame.width));
        buffer.insert("organ", Imf::Slice(Imf::UINT, bytes(frame.organ), sizeof(std::uint32_t),
                                          sizeof(std::uint32_t) * frame.width));

        // The file is closed when `file` goes out of scope, before the rename.
        Imf::OutputFile file(temporary.c_str(), header);
        file.setFrameBuffer(buffer);
        file.writePixels(height);
    });
}

} // namespace simeco::draw
