// The textures a scene's stages name (ir::DrawAssets::textures) on the device: one 2D array image, each texture
// resampled to one layer of kTextureSide x kTextureSide with its mipmaps, and the sampler the organ shader reads it
// with (render/organs/organ.frag). A scene without textures gets one white layer, so the shader always has one.
#pragma once

#include <cstdint>
#include <vector>

#include <vulkan/vulkan.h>

#include "draw/vk_objects.h"
#include "ir/draw_assets.h"

namespace simeco::vk {
class Context;
}

namespace simeco::draw {

inline constexpr std::uint32_t kTextureSide = 256;

// A texture's mip levels, 8-bit sRGB RGBA: the image resampled (bilinear) to kTextureSide on a side, then each
// level a 2 x 2 box filter of the one before, down to 1 x 1.
std::vector<std::vector<std::uint8_t>> textureMips(const ir::TextureImage& image);

class TextureArray {
public:
    TextureArray(const vk::Context& context, const std::vector<ir::TextureImage>& textures);

    VkDescriptorImageInfo descriptor() const {
        return {sampler_.get(), image_.view.get(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    }
    std::uint32_t layers() const { return layers_; }

private:
    DeviceImage image_;
    vk::DeviceHandle<VkSampler, vkDestroySampler> sampler_;
    std::uint32_t layers_ = 0;
};

} // namespace simeco::draw
