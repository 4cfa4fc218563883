// PNG and OpenEXR files written from a small frame and read back with libpng and OpenEXR; failures leave
// nothing behind.
#include <cmath>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <png.h>

#include <Imath/half.h>
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>

#include "draw/image_writers.h"

namespace simeco::test {
namespace {

namespace fs = std::filesystem;

// A fresh folder per test under the system's temporary folder, removed afterwards.
class ImageWritersTest : public ::testing::Test {
protected:
    void SetUp() override {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        folder_ = fs::temp_directory_path() / ("simeco-render-test-" + std::to_string(::getpid()) + "-" + info->name());
        fs::remove_all(folder_);
        fs::create_directories(folder_);
    }
    void TearDown() override { fs::remove_all(folder_); }

    std::vector<fs::path> filesInFolder() const {
        std::vector<fs::path> files;
        for (const auto& entry : fs::directory_iterator(folder_)) {
            files.push_back(entry.path());
        }
        return files;
    }

    fs::path folder_;
};

draw::Frame sampleFrame() {
    draw::Frame f;
    f.width = 3;
    f.height = 2;
    f.rgba = {0.0f, 0.0f, 0.0f, 1.0f, 1.0f, 0.5f, 0.25f, 1.0f, 4.0f,  0.1f, 0.01f, 1.0f,
              0.2f, 0.4f, 0.6f, 0.0f, 0.9f, 0.9f, 0.9f,  1.0f, 0.05f, 0.5f, 2.0f,  1.0f};
    f.depth = {1.0f, 2.5f, 3.75f, std::numeric_limits<float>::infinity(), 100.0f, 0.125f};
    f.plant = {0, 1, 2, draw::Frame::kNoId, 7, 123456};
    f.organ = {10, 11, 12, draw::Frame::kNoId, 70, 0xFFFFFFFEu};
    return f;
}

TEST(PreviewByteTest, MapsDarkToZeroBrightToFullAndIsMonotone) {
    EXPECT_EQ(draw::previewByte(0.0f), 0);
    EXPECT_EQ(draw::previewByte(-1.0f), 0);
    EXPECT_EQ(draw::previewByte(std::numeric_limits<float>::quiet_NaN()), 0);
    EXPECT_EQ(draw::previewByte(1000.0f), 255);
    int previous = 0;
    for (float v = 0.0f; v < 8.0f; v += 0.01f) {
        int b = draw::previewByte(v);
        EXPECT_GE(b, previous);
        previous = b;
    }
    EXPECT_GT(draw::previewByte(0.18f), 60); // mid grey stays visible
}

TEST_F(ImageWritersTest, PngReadsBackAsTheTonemappedFrame) {
    draw::Frame f = sampleFrame();
    fs::path path = folder_ / "frame.png";
    draw::writePng(path, f);
    ASSERT_EQ(filesInFolder().size(), 1u) << "no temporary left beside the image";

    png_image image{};
    image.version = PNG_IMAGE_VERSION;
    ASSERT_NE(png_image_begin_read_from_file(&image, path.c_str()), 0) << image.message;
    EXPECT_EQ(image.width, f.width);
    EXPECT_EQ(image.height, f.height);
    image.format = PNG_FORMAT_RGBA;
    std::vector<std::uint8_t> pixels(PNG_IMAGE_SIZE(image));
    ASSERT_NE(png_image_finish_read(&image, nullptr, pixels.data(), 0, nullptr), 0) << image.message;
    for (std::size_t i = 0; i < f.pixelCount(); ++i) {
        for (std::size_t c = 0; c < 3; ++c) {
            EXPECT_EQ(pixels[4 * i + c], draw::previewByte(f.rgba[4 * i + c])) << "pixel " << i << " channel " << c;
        }
        EXPECT_EQ(pixels[4 * i + 3], 255);
    }
}

TEST_F(ImageWritersTest, ExrHasEveryChannelWithItsTypeAndValues) {
    draw::Frame f = sampleFrame();
    fs::path path = folder_ / "frame.exr";
    draw::writeExr(path, f);
    ASSERT_EQ(filesInFolder().size(), 1u);

    Imf::InputFile file(path.c_str());
    const Imf::Header& header = file.header();
    Imath::Box2i window = header.dataWindow();
    ASSERT_EQ(window.max.x - window.min.x + 1, 3);
    ASSERT_EQ(window.max.y - window.min.y + 1, 2);
    const Imf::ChannelList& channels = header.channels();
    for (const char* name : {"R", "G", "B", "A"}) {
        ASSERT_NE(channels.findChannel(name), nullptr) << name;
        EXPECT_EQ(channels.findChannel(name)->type, Imf::HALF) << name;
    }
    ASSERT_NE(channels.findChannel("Z"), nullptr);
    EXPECT_EQ(channels.findChannel("Z")->type, Imf::FLOAT);
    ASSERT_NE(channels.findChannel("plant"), nullptr);
    EXPECT_EQ(channels.findChannel("plant")->type, Imf::UINT);
    ASSERT_NE(channels.findChannel("organ"), nullptr);
    EXPECT_EQ(channels.findChannel("organ")->type, Imf::UINT);

    std::size_t n = f.pixelCount();
    std::vector<float> rgba(4 * n); // read back as float: OpenEXR converts the half channels
    std::vector<float> z(n);
    std::vector<std::uint32_t> plant(n), organ(n);
    Imf::FrameBuffer buffer;
    const char* names[] = {"R", "G", "B", "A"};
    for (std::size_t c = 0; c < 4; ++c) {
        buffer.insert(names[c], Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(rgba.data() + c), 16, 16 * 3));
    }
    buffer.insert("Z", Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(z.data()), 4, 4 * 3));
    buffer.insert("plant", Imf::Slice(Imf::UINT, reinterpret_cast<char*>(plant.data()), 4, 4 * 3));
    buffer.insert("organ", Imf::Slice(Imf::UINT, reinterpret_cast<char*>(organ.data()), 4, 4 * 3));
    file.setFrameBuffer(buffer);
    file.readPixels(window.min.y, window.max.y);

    for (std::size_t i = 0; i < 4 * n; ++i) {
        EXPECT_EQ(rgba[i], static_cast<float>(Imath::half(f.rgba[i]))) << "value " << i;
    }
    for (std::size_t i = 0; i < n; ++i) {
        EXPECT_EQ(z[i], f.depth[i]) << "depth " << i;
        EXPECT_EQ(plant[i], f.plant[i]) << "plant " << i;
        EXPECT_EQ(organ[i], f.organ[i]) << "organ " << i;
    }
}

TEST_F(ImageWritersTest, UnwritablePathThrowsAndLeavesNoFile) {
    draw::Frame f = sampleFrame();
    fs::path missingFolder = folder_ / "no" / "such" / "folder";
    EXPECT_THROW(draw::writePng(missingFolder / "frame.png", f), draw::OutputError);
    EXPECT_THROW(draw::writeExr(missingFolder / "frame.exr", f), draw::OutputError);
    // A folder where the file should go: the temporary is written, the rename fails, the temporary goes.
    fs::create_directory(folder_ / "taken.png");
    fs::create_directory(folder_ / "taken.exr");
    try {
        draw::writePng(folder_ / "taken.png", f);
        ADD_FAILURE() << "writing over a folder should fail";
    } catch (const draw::OutputError& e) {
        EXPECT_NE(std::string(e.what()).find("taken.png"), std::string::npos) << e.what();
    }
    EXPECT_THROW(draw::writeExr(folder_ / "taken.exr", f), draw::OutputError);
    std::vector<fs::path> files = filesInFolder();
    EXPECT_EQ(files.size(), 2u) << "only the two folders remain";
    for (const fs::path& p : files) {
        EXPECT_TRUE(fs::is_directory(p)) << p;
    }
}

TEST_F(ImageWritersTest, InconsistentFrameThrowsBeforeCreatingAFile) {
    draw::Frame f = sampleFrame();
    f.depth.pop_back();
    EXPECT_THROW(draw::writePng(folder_ / "a.png", f), draw::OutputError);
    EXPECT_THROW(draw::writeExr(folder_ / "a.exr", f), draw::OutputError);
    draw::Frame empty;
    EXPECT_THROW(draw::writePng(folder_ / "b.png", empty), draw::OutputError);
    EXPECT_TRUE(filesInFolder().empty());
}

} // namespace
} // namespace simeco::test
