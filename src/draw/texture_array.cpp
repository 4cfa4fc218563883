#include "draw/texture_array.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "vk/buffer.h"
#include "vk/context.h"
#include "vk/vk_error.h"

namespace simeco::draw {

namespace {

constexpr VkFormat kTextureFormat = VK_FORMAT_R8G8B8A8_SRGB;

std::uint32_t mipLevels() {
    std::uint32_t levels = 1;
    for (std::uint32_t side = kTextureSide; side > 1; side /= 2) ++levels;
    return levels;
}

ir::TextureImage white() {
    ir::TextureImage image;
    image.width = image.height = 1;
    image.rgba = {255, 255, 255, 255};
    return image;
}

} // namespace

std::vector<std::vector<std::uint8_t>> textureMips(const ir::TextureImage& image) {
    std::vector<std::vector<std::uint8_t>> levels;
    std::vector<std::uint8_t> top(std::size_t(kTextureSide) * kTextureSide * 4);
    // Bilinear between the image's pixel centres, its edges clamped.
    auto texel = [&](std::int64_t x, std::int64_t y, int c) {
        x = std::clamp<std::int64_t>(x, 0, image.width - 1);
        y = std::clamp<std::int64_t>(y, 0, image.height - 1);
        return float(image.rgba[(std::size_t(y) * image.width + std::size_t(x)) * 4 + std::size_t(c)]);
    };
    for (std::uint32_t y = 0; y < kTextureSide; ++y)
        for (std::uint32_t x = 0; x < kTextureSide; ++x) {
            const float u = (float(x) + 0.5f) * float(image.width) / float(kTextureSide) - 0.5f;
            const float v = (float(y) + 0.5f) * float(image.height) / float(kTextureSide) - 0.5f;
            const float x0 = std::floor(u), y0 = std::floor(v), fx = u - x0, fy = v - y0;
            for (int c = 0; c < 4; ++c) {
                const auto ix = std::int64_t(x0), iy = std::int64_t(y0);
                const float value = (1 - fy) * ((1 - fx) * texel(ix, iy, c) + fx * texel(ix + 1, iy, c)) +
                                    fy * ((1 - fx) * texel(ix, iy + 1, c) + fx * texel(ix + 1, iy + 1, c));
                top[(std::size_t(y) * kTextureSide + x) * 4 + std::size_t(c)] = std::uint8_t(std::lround(value));
            }
        }
    levels.push_back(std::move(top));
    for (std::uint32_t side = kTextureSide / 2; side >= 1; side /= 2) {
        const std::vector<std::uint8_t>& above = levels.back();
        std::vector<std::uint8_t> level(std::size_t(side) * side * 4);
        for (std::uint32_t y = 0; y < side; ++y)
            for (std::uint32_t x = 0; x < side; ++x)
                for (std::size_t c = 0; c < 4; ++c) {
                    auto at = [&](std::uint32_t ax, std::uint32_t ay) {
                        return unsigned(above[(std::size_t(ay) * side * 2 + ax) * 4 + c]);
                    };
                    const unsigned sum = at(2 * x, 2 * y) + at(2 * x + 1, 2 * y) + at(2 * x, 2 * y + 1) +
                                         at(2 * x + 1, 2 * y + 1);
                    level[(std::size_t(y) * side + x) * 4 + c] = std::uint8_t((sum + 2) / 4);
                }
        levels.push_back(std::move(level));
    }
    return levels;
}

TextureArray::TextureArray(const vk::Context& context, const std::vector<ir::TextureImage>& textures)
    : layers_(std::max<std::uint32_t>(1, std::uint32_t(textures.size()))) {
    VkDevice device = context.device();
    const std::uint32_t levels = mipLevels();
    image_ = DeviceImage(context, kTextureFormat, VK_IMAGE_ASPECT_COLOR_BIT,
                         VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT, {kTextureSide, kTextureSide},
                         levels, layers_, VK_IMAGE_VIEW_TYPE_2D_ARRAY);
    const VkImage rawImage = image_.image.get();

    VkSamplerCreateInfo samplerInfo{};
    samplerInfo.sType = VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO;
    samplerInfo.magFilter = VK_FILTER_LINEAR;
    samplerInfo.minFilter = VK_FILTER_LINEAR;
    samplerInfo.mipmapMode = VK_SAMPLER_MIPMAP_MODE_LINEAR;
    samplerInfo.addressModeU = samplerInfo.addressModeV = samplerInfo.addressModeW = VK_SAMPLER_ADDRESS_MODE_REPEAT;
    samplerInfo.maxLod = float(levels);
    VkSampler rawSampler = VK_NULL_HANDLE;
    VK_CHECK(vkCreateSampler(device, &samplerInfo, nullptr, &rawSampler));
    sampler_ = vk::DeviceHandle<VkSampler, vkDestroySampler>(device, rawSampler);

    // Every layer's levels through one staging buffer: level by level, the layers in turn within each.
    std::vector<std::vector<std::vector<std::uint8_t>>> mips;
    for (std::uint32_t k = 0; k < layers_; ++k) mips.push_back(textureMips(textures.empty() ? white() : textures[k]));
    VkDeviceSize bytes = 0;
    for (std::uint32_t level = 0; level < levels; ++level) bytes += mips[0][level].size() * layers_;
    vk::Buffer staging(context, bytes, vk::MemoryUsage::Upload);
    std::vector<VkBufferImageCopy> copies;
    VkDeviceSize offset = 0;
    for (std::uint32_t level = 0; level < levels; ++level) {
        const std::uint32_t side = std::max(kTextureSide >> level, 1u);
        VkBufferImageCopy copy{};
        copy.bufferOffset = offset;
        copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, level, 0, layers_};
        copy.imageExtent = {side, side, 1};
        copies.push_back(copy);
        for (std::uint32_t k = 0; k < layers_; ++k) {
            std::memcpy(staging.mapped() + offset, mips[k][level].data(), mips[k][level].size());
            offset += mips[k][level].size();
        }
    }
    context.submitAndWait([&](VkCommandBuffer cmd) {
        imageTransition(cmd, rawImage, levels, layers_, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                        VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, 0, VK_PIPELINE_STAGE_TRANSFER_BIT,
                        VK_ACCESS_TRANSFER_WRITE_BIT);
        vkCmdCopyBufferToImage(cmd, staging.handle(), rawImage, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                               std::uint32_t(copies.size()), copies.data());
        imageTransition(cmd, rawImage, levels, layers_, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                        VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_TRANSFER_BIT,
                        VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT, VK_ACCESS_SHADER_READ_BIT);
    });
}

} // namespace simeco::draw
